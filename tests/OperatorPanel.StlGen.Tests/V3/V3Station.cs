using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Protocol.V3;
using OperatorPanel.Simulator.Reference.V3;
using OperatorPanel.Simulator.Stl;
using OperatorPanel.Simulator.Stl.Freeport;
using OperatorPanel.StlGen.Options;

namespace OperatorPanel.StlGen.Tests.V3;

/// <summary>
/// The generated v3 handler running in the STL interpreter behind a Freeport port, beside the reference model with the
/// same setup and the same initial memory (random V, M, Q, I; the handler's own V bytes zero in both). Each exchange
/// sends bytes on the line and returns what the interpreted handler transmitted and what the reference answers. The
/// SM bytes the CPU or the handler set by themselves are copied into the reference before every exchange; the scan
/// times of an IDENTIFY reply (and so its check) are masked in both (the handler reads them scans later).
/// </summary>
internal sealed class V3Station
{
    private static readonly TimeSpan Margin = TimeSpan.FromMilliseconds(30);

    /// <summary>Scans of the user's program time granted on top of the 5 s a reply may take: a DEFINE LIST of 32 items takes 84 scans.</summary>
    private const int SettleScans = 128;
    private readonly StlPlc _plc;
    private readonly FreeportPort _port;
    private TimeSpan _now = TimeSpan.FromMilliseconds(50);

    /// <param name="options">The handler's options (protocol 3 is set here).</param>
    /// <param name="random">The initial memory's bytes.</param>
    /// <param name="userProgram">The user's own program merged into the handler's .awl text before it is loaded; none: the handler alone.</param>
    public V3Station(HandlerOptions options, Random random, Func<string, string>? userProgram = null)
    {
        Options = options with { Protocol = 3 };
        Generated = HandlerGenerator.Generate(Options);
        if (!Generated.Ok)
        {
            throw new InvalidOperationException("not generated: " + string.Join("; ", Generated.Diagnostics));
        }

        var load = StlProgramLoader.Load(userProgram is null ? Generated.AwlText : userProgram(Generated.AwlText), Options.Cpu);
        _plc = new StlPlc(load.Program ?? throw new InvalidOperationException("not loaded: " + string.Join("; ", load.Diagnostics)));
        Line = new LineSettings(Options.BaudRate, Options.Parity, Options.DataBits);
        _port = new FreeportPort(Options.Port, _plc.Memory, Options.Cpu, Line);
        _plc.AttachPort(_port);
        Reference = new ReferenceHandler(new HandlerSetup(
            new Station(Options.Station), Options.Cpu, Options.Compact ? HandlerShape.Compact : HandlerShape.Full, Options.Port, (byte)Options.EffectiveV3WriteMask,
            (byte)Options.EffectiveEndTimeoutMs, Options.AllowStop && !Options.Compact, Options.EffectiveV3First));
        Fill(random);
        _plc.RunUntil(_now);
    }

    public HandlerOptions Options { get; }

    public HandlerGenerationResult Generated { get; }

    public ReferenceHandler Reference { get; }

    public LineSettings Line { get; }

    public StlPlc Plc => _plc;

    public Station Station => new(Options.Station);

    /// <summary>The port's RCV is armed: the station hears the next request.</summary>
    public bool Receiving => _port.IsReceiving;

    public void Poke(ProtocolArea area, int offset, params byte[] bytes)
    {
        bytes.CopyTo(Reference.Memory.Area(area), offset);
        bytes.CopyTo(area == ProtocolArea.I ? _plc.InputImage : _plc.Memory.Area(area), offset);
    }

    /// <summary>Sends <paramref name="message"/> (one RCV message); returns (interpreted handler's bytes, reference's reply).</summary>
    public (byte[] Stl, byte[] Reference) Exchange(byte[] message)
    {
        CopyCpuOwnedSm();
        var expected = Reference.HandleMessage(message) ?? [];
        _port.Deliver(message, _now);
        var at = _now + (Line.CharacterTime * message.Length);
        var deadline = at + TimeSpan.FromMilliseconds(Options.EffectiveEndTimeoutMs) + Margin + (Line.CharacterTime * expected.Length);
        var got = new List<byte>();
        var times = new List<TimeSpan>();
        var t = at;
        _plc.RunUntil(t);
        while (_plc.Fault is null && _plc.Mode == Simulator.Reference.OperatingMode.Run)
        {
            Take(got, times);
            var settled = !_port.IsTransmitting && _port.IsReceiving;
            if (settled && (t >= deadline || (expected.Length > 0 && got.Count >= expected.Length)))
            {
                break;
            }

            if (t >= deadline + TimeSpan.FromSeconds(5) + (_plc.UserProgramTime * SettleScans))
            {
                throw new InvalidOperationException($"the port never settled; sent so far {Convert.ToHexString([.. got])}");
            }

            t += TimeSpan.FromMilliseconds(1);
            _plc.RunUntil(t);
        }

        Take(got, times);
        LongestPause = times.Count < 2 ? TimeSpan.Zero : times.Zip(times.Skip(1), (a, b) => b - a - Line.CharacterTime).Max();
        if (_plc.Fault is { } fault && fault.Code != "Stop")
        {
            throw new InvalidOperationException($"the handler faulted: {fault}");
        }

        _now = t + TimeSpan.FromMilliseconds(Options.EffectiveEndTimeoutMs + 5);
        _plc.RunUntil(_now);
        return (Masked([.. got], message), Masked(expected, message));
    }

    /// <summary>The longest pause between two characters of the last exchange's reply (zero when they left back to back).</summary>
    public TimeSpan LongestPause { get; private set; }

    private void Take(List<byte> got, List<TimeSpan> times)
    {
        foreach (var c in _port.TakeTransmitted())
        {
            got.Add(c.Value);
            times.Add(c.At);
        }
    }

    /// <summary>IDENTIFY's scan times (payload bytes 18-23) and its check.</summary>
    public static byte[] Masked(byte[] reply, byte[] request)
    {
        if (reply.Length == Limits.ReplyBytes(Identity.PayloadBytes) && request.Length > 3 && (request[3] & 0x0F) == (byte)Command.Identify && reply[2] == (byte)ReplyStatus.Ok)
        {
            var masked = (byte[])reply.Clone();
            Array.Fill<byte>(masked, 0xEE, Limits.ReplyHead + 18, 6);
            Array.Fill<byte>(masked, 0xEE, masked.Length - WordCheck.Bytes, WordCheck.Bytes);
            return masked;
        }

        return reply;
    }

    private void Fill(Random random)
    {
        Randomize(random, _plc.Memory.V, Reference.Memory.V);
        Randomize(random, _plc.Memory.M, Reference.Memory.M);
        Randomize(random, _plc.Memory.Q, Reference.Memory.Q);
        Randomize(random, _plc.InputImage, Reference.Memory.I);
        Array.Copy(_plc.InputImage, _plc.Memory.I, _plc.Memory.I.Length);
        for (var b = Generated.Stats!.FirstVByte; b <= Generated.Stats.LastVByte; b++)
        {
            (_plc.Memory.V[b], Reference.Memory.V[b]) = (0, 0);
        }
    }

    private static void Randomize(Random random, byte[] a, byte[] b)
    {
        random.NextBytes(a);
        a.CopyTo(b, 0);
    }

    private void CopyCpuOwnedSm()
    {
        var from = _plc.Memory.SM;
        var to = Reference.Memory.SM;
        for (var b = 0; b < to.Length; b++)
        {
            if (b < 30 || b is 30 or 34 or 130 or (>= 86 and <= 94) or (>= 186 and <= 194))
            {
                to[b] = from[b];
            }
        }
    }
}
