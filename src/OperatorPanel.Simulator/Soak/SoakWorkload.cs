using System.Buffers.Binary;
using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Line;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Writes;

namespace OperatorPanel.Simulator.Soak;

/// <summary>
/// The panel's side of a soak run: one step at a time, an IDENTIFY (until one gets through), a write or a refresh, by
/// the seed, until the time is up; it records the writes and the good values shown for the judge. Writes go to the
/// region's writable addresses in turn (an order shuffled by the seed), so every one is written within a few steps.
/// </summary>
internal sealed class SoakWorkload(SoakSetup setup, Bus bus, TimeProvider time)
{
    /// <summary>Longest one write or refresh may take, retries and all, before the run is declared stuck.</summary>
    private static readonly TimeSpan StepLimit = TimeSpan.FromSeconds(30);

    /// <summary>IDENTIFY attempts before the run goes on without: at 1% flips its 41-byte exchange rarely survives.</summary>
    private const int IdentifyAttempts = 30;

    /// <summary>Until identified, one step in this many is an IDENTIFY, so the attempts spread over the run.</summary>
    private const int IdentifyEvery = 8;

    private readonly Dictionary<PlcAddress, bool> _bits = [];
    private int _identifyAttempts;
    private int _steps;

    public List<SoakWrite> Writes { get; } = [];

    /// <summary>The handler answered IDENTIFY, so the bus polls its list with READ LIST as the panel does.</summary>
    public bool Identified { get; private set; }

    public List<ShownValue> Shown { get; } = [];

    public async Task RunAsync(Task[] running, CancellationToken cancellationToken)
    {
        var random = new Random(setup.Seed);
        var targets = setup.Region.Written.ToArray();
        random.Shuffle(targets);
        var started = time.GetTimestamp();
        var previous = started;
        while (time.GetElapsedTime(started) < setup.Duration && !cancellationToken.IsCancellationRequested)
        {
            if (running.FirstOrDefault(t => t.IsFaulted) is { } failed)
            {
                await failed.ConfigureAwait(false);
            }

            var stepStart = time.GetTimestamp();
            if (!Identified && _identifyAttempts < IdentifyAttempts && _steps++ % IdentifyEvery == 0)
            {
                await IdentifyAsync(cancellationToken).ConfigureAwait(false);
            }
            else if (random.Next(2) == 0 && targets.Length > 0)
            {
                await WriteAsync(targets[Writes.Count % targets.Length], cancellationToken).ConfigureAwait(false);
            }
            else
            {
                await RefreshAsync(previous, cancellationToken).ConfigureAwait(false);
            }

            previous = stepStart;
        }
    }

    /// <summary>
    /// The <paramref name="number"/>-th write's value: a double word k x 2654435761, a word k x 40503 (both odd, so no
    /// two of the run's first 2^32 or 2^16 writes store the same value: a value found names its write); a byte k x 167
    /// (repeats after 256 writes); a bit the opposite of the last one written there.
    /// </summary>
    private ImmutableArray<byte> ValueOf(PlcAddress address, int number)
    {
        var bytes = new byte[address.Width.ByteCount()];
        switch (address.Width)
        {
            case AccessWidth.DoubleWord:
                BinaryPrimitives.WriteUInt32BigEndian(bytes, unchecked((uint)number * 2654435761u));
                break;
            case AccessWidth.Word:
                BinaryPrimitives.WriteUInt16BigEndian(bytes, unchecked((ushort)(number * 40503)));
                break;
            case AccessWidth.Byte:
                bytes[0] = unchecked((byte)(number * 167));
                break;
            case AccessWidth.Bit:
                var bit = !_bits.GetValueOrDefault(address);
                _bits[address] = bit;
                bytes[0] = bit ? (byte)1 : (byte)0;
                break;
        }

        return [.. bytes];
    }

    /// <summary>IDENTIFY as the panel sends it on connecting; without it the list reader asks for it itself.</summary>
    private async Task IdentifyAsync(CancellationToken cancellationToken)
    {
        _identifyAttempts++;
        // A failure means noise took it: the run polls as a panel that has not identified the handler yet.
        if ((await bus.IdentifyAsync(setup.Station, cancellationToken).WaitAsync(StepLimit, cancellationToken).ConfigureAwait(false)).Response is IdentifyResponse)
        {
            Identified = true;
        }
    }

    private async Task WriteAsync(PlcAddress address, CancellationToken cancellationToken)
    {
        var number = Writes.Count + 1;
        var value = ValueOf(address, number);
        var request = address.Width == AccessWidth.Bit
            ? WriteRequest.Bit(setup.Station, address, value[0] != 0)
            : WriteRequest.Bytes(setup.Station, address, value);
        var sent = time.GetTimestamp();
        var outcome = await bus.WriteAsync(request, cancellationToken).WaitAsync(StepLimit, cancellationToken).ConfigureAwait(false);
        Writes.Add(new SoakWrite(number, address, value, sent, time.GetTimestamp(), outcome));
    }

    private async Task RefreshAsync(long from, CancellationToken cancellationToken)
    {
        await bus.RefreshAsync(cancellationToken).WaitAsync(StepLimit, cancellationToken).ConfigureAwait(false);
        var until = time.GetTimestamp();
        foreach (var address in setup.Region.Items)
        {
            if (bus.TryGetValue(setup.Station, address, out var value) && value.Quality == ValueQuality.Good && value.HasValue)
            {
                Shown.Add(new ShownValue(address, value.Raw, from, until));
            }
        }
    }
}
