using System.Text;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Simulator.Reference;
using OperatorPanel.Simulator.Stl;
using OperatorPanel.Simulator.Stl.Freeport;
using OperatorPanel.StlGen.Handler;
using OperatorPanel.StlGen.Options;

namespace OperatorPanel.StlGen.Tests.Streaming;

/// <summary>
/// The generated handler alone in the interpreter, with a user's program as time per scan, beside the reference model
/// on the same memory (a pattern in V from byte 0). Serves one request and keeps what the port sent with its times,
/// every interrupt run, and when OP_PANEL's work on the request ended (STEP back to 0 at a scan's end).
/// </summary>
internal sealed class ReplyChunkRig
{
    private static readonly TimeSpan Step = TimeSpan.FromMilliseconds(0.25);
    private readonly FreeportPort _port;
    private readonly int _step;
    private readonly List<(TimeSpan EndedAt, byte Step)> _scans = [];
    private TimeSpan _now = TimeSpan.FromMilliseconds(50);

    public ReplyChunkRig(HandlerOptions options, TimeSpan userProgram)
    {
        var generated = HandlerGenerator.Generate(options);
        AwlText = generated.AwlText;
        Plc = new StlPlc(StlProgramLoader.Load(AwlText, options.Cpu).Program!) { UserProgramTime = userProgram };
        Line = new LineSettings(options.BaudRate, options.Parity, options.DataBits);
        _port = new FreeportPort(options.Port, Plc.Memory, options.Cpu, Line);
        Plc.AttachPort(_port);
        Reference = new ReferencePlc(new HandlerConfig(
            new Station(options.Station), options.Cpu, options.Port, (byte)options.WriteMask, (byte)options.ReplyDelayMs, options.EffectiveBufferStart,
            options.AllowStop, options.CopyBytes));
        byte[] pattern = [.. Enumerable.Range(0, 256).Select(i => (byte)(i * 7))];
        pattern.CopyTo(Plc.Memory.V, 0);
        pattern.CopyTo(Reference.Memory.Area(ProtocolArea.V), 0);
        _step = options.EffectiveBufferStart + HandlerLayout.Step;
        Plc.InterruptServed += (_, run) => Runs.Add(run);
        Plc.ScanCompleted += (_, scan) => _scans.Add((scan.EndedAt, Plc.Memory.V[_step]));
        Plc.RunUntil(_now);
    }

    public string AwlText { get; }

    public StlPlc Plc { get; }

    public ReferencePlc Reference { get; }

    public LineSettings Line { get; }

    public List<StlInterruptRun> Runs { get; } = [];

    /// <summary>The start of the last scan begun: the one in which the CPU went to STOP, once it has.</summary>
    public TimeSpan LastScanStart => _scans[^1].EndedAt;

    /// <summary>
    /// Sends <paramref name="frame"/> (and <paramref name="during"/> once the reply's first character has left) and
    /// runs until the port receives again after a '&gt;', the CPU stops, or 3 s have passed.
    /// </summary>
    public ServedReply Serve(byte[] frame, byte[]? during = null)
    {
        Runs.Clear();
        _scans.Clear();
        var expected = Reference.HandleFrame(frame) is { } reply ? Encoding.ASCII.GetString(reply) : "";
        _port.Deliver(frame, _now);
        var requestEnd = _now + (Line.CharacterTime * frame.Length);
        var sent = new List<WireCharacter>();
        var receivingBeforeEnd = false;
        var t = _now;
        var ended = false;
        while (Plc.Fault is null && t < requestEnd + TimeSpan.FromSeconds(3) && !(ended && _port.IsReceiving))
        {
            t += Step;
            Plc.RunUntil(t);
            foreach (var c in _port.TakeTransmitted())
            {
                sent.Add(c);
                ended |= c.Value == (byte)'>';
            }

            receivingBeforeEnd |= sent.Count > 0 && !ended && _port.IsReceiving;

            if (during is not null && sent.Count > 0)
            {
                _port.Deliver(during, t);
                during = null;
            }
        }

        _now = t + TimeSpan.FromMilliseconds(20);
        Plc.RunUntil(_now);
        var after = _scans.Where(s => s.EndedAt > requestEnd).SkipWhile(s => s.Step == 0);
        var checkDone = after.Where(s => s.Step == 0).Select(s => s.EndedAt).DefaultIfEmpty(TimeSpan.MaxValue).First();
        return new ServedReply(
            new string([.. sent.Select(c => (char)c.Value)]), expected, requestEnd, sent, checkDone, receivingBeforeEnd,
            Runs.Count(r => r.Event is 9 or 26));
    }
}
