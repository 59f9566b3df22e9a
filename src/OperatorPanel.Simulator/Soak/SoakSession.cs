using System.Buffers.Binary;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Line;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Link.V3;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Transport;
using OperatorPanel.Core.Writes;
using OperatorPanel.Simulator.Hosting;
using Serilog;

namespace OperatorPanel.Simulator.Soak;

/// <summary>
/// A soak run end to end: the simulated PLC (behind an <see cref="ExecutedWriteObserver"/>) on its pty, the
/// <see cref="NoisyLineProxy"/> between the two pty pairs, and the real panel stack (SerialPortTransport, V3Link, Bus
/// and its polling loop, speaking protocol v3) on the panel's pty. The panel alternates, by the seed, between writing a new value to a double word
/// of the <see cref="SoakRegion"/> and refreshing the region, until the duration is up; then the
/// <see cref="SoakJudge"/> holds what it showed and confirmed against what the PLC executed.
/// </summary>
public static class SoakSession
{
    /// <summary>Longest one write or refresh may take, retries and all, before the run is declared stuck.</summary>
    private static readonly TimeSpan StepLimit = TimeSpan.FromSeconds(30);

    public static async Task<SoakFigures> RunAsync(SoakSetup setup, TimeProvider time, ILogger? log, CancellationToken cancellationToken)
    {
        ArgumentNullException.ThrowIfNull(setup);
        ArgumentNullException.ThrowIfNull(time);
        log ??= Serilog.Core.Logger.None;
        var region = setup.Region;
        var initial = setup.Memory.V.AsSpan(region.First, region.Bytes).ToArray();
        var observer = new ExecutedWriteObserver(setup.Line, setup.Memory, Watched(setup), time);
        var plcPort = new SerialPortTransport(Serial(setup, setup.PlcPort));
        var host = new SimulatedPlcHost(plcPort, observer, time, log);
        var proxyPanel = new SerialPortTransport(Serial(setup, setup.ProxyPanelSide));
        var proxyPlc = new SerialPortTransport(Serial(setup, setup.ProxyPlcSide));
        var proxy = new NoisyLineProxy(proxyPanel, proxyPlc, setup.Faults, setup.Seed);
        var panelSerial = Serial(setup, setup.PanelPort);
        var items = region.Slots.Select(s => new WatchedItem(setup.Station, Address(s)));
        await using var bus = Bus.StartV3(
            new V3Link(new SerialPortTransport(panelSerial), LinkOptions.For(panelSerial), time, log),
            PollPlanner.Build(items, new Dictionary<Station, Core.Cpu.CpuProfile> { [setup.Station] = setup.Cpu }),
            new BusSettings { Mode = RefreshMode.OnDemand },
            time,
            log);

        using var stop = CancellationTokenSource.CreateLinkedTokenSource(cancellationToken);
        var running = new[]
        {
            Task.Run(() => host.RunAsync(stop.Token), stop.Token),
            Task.Run(() => proxy.RunAsync(stop.Token), stop.Token),
        };
        var started = time.GetTimestamp();
        var work = new SoakWork(setup, bus, time);
        try
        {
            await work.RunAsync(running, stop.Token).ConfigureAwait(false);
        }
        finally
        {
            await bus.StopPollingAsync().ConfigureAwait(false);
            await stop.CancelAsync().ConfigureAwait(false);
            await Ended(running).ConfigureAwait(false);
            await proxyPanel.DisposeAsync().ConfigureAwait(false);
            await proxyPlc.DisposeAsync().ConfigureAwait(false);
            await plcPort.DisposeAsync().ConfigureAwait(false);
        }

        var judgement = new SoakJudge(region, initial).Judge(work.Writes, work.Shown, observer.Changes);
        var statistics = bus.StatisticsFor(setup.Station);
        return new SoakFigures
        {
            Faults = setup.Faults.ToString(),
            Seed = setup.Seed,
            Elapsed = time.GetElapsedTime(started),
            Exchanges = statistics.Requests,
            Retries = statistics.Retries,
            Timeouts = statistics.Timeouts,
            CorruptReplies = statistics.CorruptFrames,
            NegativeReplies = statistics.NegativeReplies,
            ValuesShownGood = judgement.ValuesShownGood,
            WrongValuesShownGood = judgement.WrongValuesShownGood,
            WritesSent = judgement.WritesSent,
            WritesConfirmed = judgement.WritesConfirmed,
            ConfirmedByReadBack = judgement.ConfirmedByReadBack,
            FalseConfirmations = judgement.FalseConfirmations,
            WritesOutOfOrder = judgement.WritesOutOfOrder,
            WritesNotConfirmed = judgement.WritesNotConfirmed,
            NotConfirmedButExecuted = judgement.NotConfirmedButExecuted,
            FalseNotApplied = judgement.FalseNotApplied,
            ExecutedNeverSent = judgement.ExecutedNeverSent,
            Findings = judgement.Findings,
            CharactersOnLine = proxy.ToPlc.Characters + proxy.ToPanel.Characters,
            BitsFlipped = proxy.ToPlc.BitsFlipped + proxy.ToPanel.BitsFlipped,
            CharactersDropped = proxy.ToPlc.CharactersDropped + proxy.ToPanel.CharactersDropped,
            FramesDropped = proxy.ToPlc.FramesDropped + proxy.ToPanel.FramesDropped,
            LinesIdentified = work.Identified ? 1 : 0,
        };
    }

    internal static PlcAddress Address(int slot) => PlcAddress.ForBytes(MemoryArea.V, slot, AccessWidth.DoubleWord);

    private static SerialSettings Serial(SoakSetup setup, string port) => new() { PortName = port, BaudRate = setup.Baud };

    private static IEnumerable<WatchedBytes> Watched(SoakSetup setup) =>
    [
        new(ProtocolArea.V, 0, setup.HandlerFirstByte),
        new(ProtocolArea.M, 0, setup.Memory.M.Length),
        new(ProtocolArea.Q, 0, setup.Memory.Q.Length),
    ];

    /// <summary>Waits for the background parts to stop; their cancellation is the expected end.</summary>
    private static async Task Ended(Task[] running)
    {
        try
        {
            await Task.WhenAll(running).WaitAsync(TimeSpan.FromSeconds(5)).ConfigureAwait(false);
        }
        catch (OperationCanceledException)
        {
            // Cancelled on purpose: every part ends this way.
        }
    }

    /// <summary>The panel's side of the run: its writes and the good values it showed, recorded for the judge.</summary>
    private sealed class SoakWork(SoakSetup setup, Bus bus, TimeProvider time)
    {
        /// <summary>IDENTIFY attempts before the run goes on without: at 1% flips its 41-byte exchange rarely survives.</summary>
        private const int IdentifyAttempts = 30;

        /// <summary>Until identified, one step in this many is an IDENTIFY, so the attempts spread over the run.</summary>
        private const int IdentifyEvery = 8;

        private int _identifyAttempts;
        private int _steps;

        public List<SoakWrite> Writes { get; } = [];

        /// <summary>The handler answered IDENTIFY, so the bus polls its list with READ LIST as the panel does.</summary>
        public bool Identified { get; private set; }

        public List<ShownValue> Shown { get; } = [];

        public async Task RunAsync(Task[] running, CancellationToken cancellationToken)
        {
            var random = new Random(setup.Seed);
            var slots = setup.Region.Slots;
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
                else if (random.Next(2) == 0)
                {
                    await WriteAsync(slots[random.Next(slots.Count)], cancellationToken).ConfigureAwait(false);
                }
                else
                {
                    await RefreshAsync(previous, cancellationToken).ConfigureAwait(false);
                }

                previous = stepStart;
            }
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

        /// <summary>The k-th write's value: k times an odd constant, so no two writes of the run store the same value.</summary>
        private static uint ValueOf(int number) => unchecked((uint)number * 2654435761u);

        private async Task WriteAsync(int slot, CancellationToken cancellationToken)
        {
            var number = Writes.Count + 1;
            var value = ValueOf(number);
            var data = new byte[4];
            BinaryPrimitives.WriteUInt32BigEndian(data, value);
            var outcome = await bus.WriteAsync(WriteRequest.Bytes(setup.Station, Address(slot), [.. data]), cancellationToken)
                .WaitAsync(StepLimit, cancellationToken).ConfigureAwait(false);
            Writes.Add(new SoakWrite(number, slot, value, outcome));
        }

        private async Task RefreshAsync(long from, CancellationToken cancellationToken)
        {
            await bus.RefreshAsync(cancellationToken).WaitAsync(StepLimit, cancellationToken).ConfigureAwait(false);
            var until = time.GetTimestamp();
            foreach (var slot in setup.Region.Slots)
            {
                if (bus.TryGetValue(setup.Station, Address(slot), out var value) && value.Quality == ValueQuality.Good && value.HasValue)
                {
                    Shown.Add(new ShownValue(slot, BinaryPrimitives.ReadUInt32BigEndian(value.Raw.AsSpan()), from, until));
                }
            }
        }
    }
}
