using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Simulator.Stl;
using OperatorPanel.Simulator.Stl.Freeport;
using OperatorPanel.StlGen;
using OperatorPanel.StlGen.Options;

namespace OperatorPanel.Cli.Bench;

/// <summary>
/// Runs the handler StlGen generates in the STL interpreter at the published instruction times (Simulator StlTiming,
/// docs/sources/s7200-facts.md section 6), with the line's own program as <see cref="StlPlc.UserProgramTime"/> per scan,
/// and serves it the requests of a refresh one after the other, so each one finds the state the earlier ones left
/// (lists defined, change copies filled). For each request it takes the reply's times from the simulated port: its
/// first character's start and its '&gt;''s end, measured from the request's '&gt;'. The user's program is a time and
/// not STL: the interpreter spends it after OB1's handler call and serves interrupts in it, which is all the handler
/// sees of a line's program, and the generated handler stays the whole loaded program.
/// </summary>
internal sealed class HandlerProbe
{
    private static readonly TimeSpan Step = TimeSpan.FromMilliseconds(0.5);
    private static readonly TimeSpan GiveUp = TimeSpan.FromSeconds(2);

    /// <summary>
    /// Scans without handler work granted on top of <see cref="GiveUp"/>, counted from the handler's last work (a scan
    /// above an idle one, or a character sent), not from the request: a request's work takes up to 84 scans (DEFINE LIST
    /// of 32 SM items, generate --stats --protocol 3), each as long as the user's program (--scan-ms), so a bound counted
    /// from the request's end gave up on a DEFINE LIST still being served at 97 ms scans and more.
    /// </summary>
    private const int GiveUpScans = 8;

    /// <summary>Scans after the request's end after which the probe gives up even on a handler still working (one that never ends).</summary>
    private const int MostScans = 1024;
    private static readonly TimeSpan IdleRun = TimeSpan.FromMilliseconds(50);

    /// <summary>
    /// Scans the idle run lasts at least: at a user's program of 50 ms and more, <see cref="IdleRun"/> held no whole scan,
    /// so an idle scan's instructions were 0 and every scan counted as the handler's work.
    /// </summary>
    private const int IdleScans = 3;

    private readonly StlPlc _plc;
    private readonly FreeportPort _port;
    private readonly LineSettings _line;
    private readonly List<(StlScan Scan, long Instructions)> _scans = [];
    private readonly List<StlInterruptRun> _runs = [];
    private readonly Func<IReadOnlyList<byte>, bool> _replyEnded;
    private readonly long _idleInstructions;
    private long _instructionsAtScanStart;
    private TimeSpan _now = TimeSpan.FromMilliseconds(50);

    private HandlerProbe(StlPlc plc, FreeportPort port, LineSettings line, Func<IReadOnlyList<byte>, bool> replyEnded)
    {
        (_plc, _port, _line, _replyEnded) = (plc, port, line, replyEnded);
        _plc.ScanCompleted += (_, scan) =>
        {
            _scans.Add((scan, _plc.InstructionsExecuted - _instructionsAtScanStart));
            _instructionsAtScanStart = _plc.InstructionsExecuted;
        };
        _plc.InterruptServed += (_, run) => _runs.Add(run);
        _plc.RunUntil(_now);
        _scans.Clear();
        _now += Max(IdleRun, _plc.UserProgramTime * IdleScans);
        _plc.RunUntil(_now);
        _idleInstructions = _scans.Count == 0 ? 0 : _scans.Max(s => s.Instructions);
    }

    public static bool TryCreate(CpuProfile cpu, Station station, LineSettings line, int replyDelayMs, TimeSpan userProgram, out HandlerProbe? probe, out string error)
    {
        ArgumentNullException.ThrowIfNull(cpu);
        var options = Options(cpu, station, line) with { Protocol = 2, ReplyDelayMs = replyDelayMs };
        return TryCreate(options, line, userProgram, reply => reply[^1] == (byte)'>', out probe, out error);
    }

    /// <summary>
    /// The protocol 3 handler (full: with the list), whose reply ends after LEN bytes (docs/protocol.md section 1.6),
    /// never at a byte's value.
    /// </summary>
    public static bool TryCreateV3(CpuProfile cpu, Station station, LineSettings line, TimeSpan userProgram, out HandlerProbe? probe, out string error)
    {
        ArgumentNullException.ThrowIfNull(cpu);
        var options = Options(cpu, station, line) with { Protocol = 3 };
        return TryCreate(options, line, userProgram, reply => reply.Count >= 2 && reply.Count >= reply[1], out probe, out error);
    }

    private static HandlerOptions Options(CpuProfile cpu, Station station, LineSettings line) => new()
    {
        Cpu = cpu,
        Station = station.Address,
        BaudRate = line.Baud,
        Parity = line.Parity,
        DataBits = line.DataBits,
    };

    /// <summary>The handler the probe runs, as generated (.awl text).</summary>
    public string AwlText { get; private init; } = string.Empty;

    /// <summary>The last reply's bytes, each with the end of its stop bit, counted from the request's last character.</summary>
    public IReadOnlyList<(byte Value, TimeSpan At)> LastReply { get; private set; } = [];

    private static bool TryCreate(HandlerOptions options, LineSettings line, TimeSpan userProgram, Func<IReadOnlyList<byte>, bool> replyEnded, out HandlerProbe? probe, out string error)
    {
        probe = null;
        var cpu = options.Cpu;
        var generated = HandlerGenerator.Generate(options);
        if (!generated.Ok)
        {
            error = $"the handler cannot be generated: {string.Join("; ", generated.Diagnostics)}";
            return false;
        }

        var load = StlProgramLoader.Load(generated.AwlText, cpu);
        if (load.Program is null)
        {
            error = $"the generated handler does not load: {string.Join("; ", load.Diagnostics)}";
            return false;
        }

        var plc = new StlPlc(load.Program) { UserProgramTime = userProgram };
        var port = new FreeportPort(options.Port, plc.Memory, cpu, line);
        plc.AttachPort(port);
        probe = new HandlerProbe(plc, port, line, replyEnded) { AwlText = generated.AwlText };
        error = string.Empty;
        return true;
    }

    /// <summary>
    /// Sends <paramref name="frame"/> and runs the PLC until the reply has left (its '&gt;' in v2, its LEN bytes in v3)
    /// and the port receives again. False when the handler did not answer (it keeps silent on a request it does not understand:
    /// given up <see cref="GiveUp"/> and <see cref="GiveUpScans"/> scans after its last work) or faulted.
    /// <paramref name="replyChars"/>: the characters the handler sent.
    /// </summary>
    public bool TryServe(byte[] frame, out HandlerCost? cost, out int replyChars, out string error)
    {
        ArgumentNullException.ThrowIfNull(frame);
        _scans.Clear();
        _runs.Clear();
        _port.Deliver(frame, _now);
        var requestEnd = _now + (_line.CharacterTime * frame.Length);
        var lastWork = requestEnd;
        var mostScans = requestEnd + GiveUp + (_plc.UserProgramTime * MostScans);
        var t = _now;
        TimeSpan? replyStart = null;
        var replyEnd = TimeSpan.Zero;
        var ended = false;
        var reply = new List<(byte Value, TimeSpan At)>();
        var scansSeen = 0;
        while (_plc.Fault is null && t < Min(lastWork + GiveUp + (_plc.UserProgramTime * GiveUpScans), mostScans) && !(ended && !_port.IsTransmitting && _port.IsReceiving))
        {
            t += Step;
            _plc.RunUntil(t);
            if (_scans.Skip(scansSeen).Any(s => s.Instructions > _idleInstructions))
            {
                lastWork = t;
            }

            scansSeen = _scans.Count;
            foreach (var c in _port.TakeTransmitted())
            {
                lastWork = t;
                replyStart ??= c.At - _line.CharacterTime;
                reply.Add((c.Value, c.At - requestEnd));
                ended |= _replyEnded([.. reply.Select(r => r.Value)]);
                replyEnd = c.At;
            }
        }

        _now = t + Step;
        _plc.RunUntil(_now);
        (replyChars, LastReply) = (reply.Count, reply);
        (cost, error) = (null, string.Empty);
        if (_plc.Fault is { } fault)
        {
            error = $"the handler faulted: {fault}";
            return false;
        }

        if (replyStart is not { } start || !ended)
        {
            error = "the generated handler did not answer";
            return false;
        }

        cost = new HandlerCost(WorkScans(requestEnd), start - requestEnd, replyEnd - start, "measured: generated handler in the interpreter");
        return true;
    }

    private static TimeSpan Min(TimeSpan a, TimeSpan b) => a < b ? a : b;

    private static TimeSpan Max(TimeSpan a, TimeSpan b) => a > b ? a : b;

    /// <summary>
    /// The scans from the request's end to the last one in which the handler executed more than an idle scan (the
    /// slice that ends the reply's check), as `opanel generate --stats` counts them.
    /// </summary>
    private int WorkScans(TimeSpan requestEnd)
    {
        var program = _scans.Where(s => s.Scan.EndedAt > requestEnd).Select(s =>
            s.Instructions - _runs.Where(r => r.StartedAt >= s.Scan.StartedAt && r.StartedAt < s.Scan.EndedAt).Sum(r => r.Instructions)).ToList();
        return program.FindLastIndex(instructions => instructions > _idleInstructions) + 1;
    }
}
