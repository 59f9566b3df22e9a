using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Simulator.Stl;
using OperatorPanel.Simulator.Stl.Freeport;
using OperatorPanel.StlGen;
using OperatorPanel.StlGen.Options;

namespace OperatorPanel.Cli.Bench;

/// <summary>
/// Runs the handler StlGen generates, as the whole program, in the STL interpreter at the published instruction times
/// (Simulator StlTiming, docs/sources/s7200-facts.md section 6) and serves it the requests of a refresh one after the
/// other, so each one finds the state the earlier ones left (lists defined, change copies filled). For each request it
/// gives the scans and the time from the request's '&gt;' until the handler attached the reply delay.
/// </summary>
internal sealed class HandlerProbe
{
    private static readonly TimeSpan Step = TimeSpan.FromMilliseconds(0.5);
    private static readonly TimeSpan GiveUp = TimeSpan.FromSeconds(2);

    private readonly StlPlc _plc;
    private readonly FreeportPort _port;
    private readonly LineSettings _line;
    private readonly TimeSpan _replyDelay;
    private readonly List<StlScan> _scans = [];
    private TimeSpan _now = TimeSpan.FromMilliseconds(50);

    private HandlerProbe(StlPlc plc, FreeportPort port, LineSettings line, TimeSpan replyDelay)
    {
        (_plc, _port, _line, _replyDelay) = (plc, port, line, replyDelay);
        _plc.ScanCompleted += (_, scan) => _scans.Add(scan);
        _plc.RunUntil(_now);
    }

    public static bool TryCreate(CpuProfile cpu, Station station, LineSettings line, int replyDelayMs, out HandlerProbe? probe, out string error)
    {
        ArgumentNullException.ThrowIfNull(cpu);
        probe = null;
        var options = new HandlerOptions
        {
            Cpu = cpu,
            Station = station.Address,
            BaudRate = line.Baud,
            Parity = line.Parity,
            DataBits = line.DataBits,
            ReplyDelayMs = replyDelayMs,
        };
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

        var plc = new StlPlc(load.Program);
        var port = new FreeportPort(options.Port, plc.Memory, cpu, line);
        plc.AttachPort(port);
        probe = new HandlerProbe(plc, port, line, TimeSpan.FromMilliseconds(replyDelayMs));
        error = string.Empty;
        return true;
    }

    /// <summary>
    /// Sends <paramref name="frame"/> and runs the PLC until the reply has left and the port receives again. False
    /// when the handler did not answer (it keeps silent on a request it does not understand) or faulted.
    /// <paramref name="replyChars"/>: the characters the handler sent.
    /// </summary>
    public bool TryServe(byte[] frame, out HandlerCost? cost, out int replyChars, out string error)
    {
        ArgumentNullException.ThrowIfNull(frame);
        _scans.Clear();
        _port.Deliver(frame, _now);
        var requestEnd = _now + (_line.CharacterTime * frame.Length);
        var giveUp = requestEnd + GiveUp;
        var t = _now;
        TimeSpan? replyStart = null;
        var ended = false;
        replyChars = 0;
        while (_plc.Fault is null && t < giveUp && !(ended && !_port.IsTransmitting && _port.IsReceiving))
        {
            t += Step;
            _plc.RunUntil(t);
            foreach (var c in _port.TakeTransmitted())
            {
                replyStart ??= c.At - _line.CharacterTime;
                replyChars++;
                ended |= c.Value == (byte)'>';
            }
        }

        _now = t + Step;
        _plc.RunUntil(_now);
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

        // The reply delay's timed interrupt is attached when the work on the request is done; the reply starts one
        // delay later, so the work ended one delay before the reply's first character.
        var workDone = start - _replyDelay;
        var scans = _scans.Count(s => s.EndedAt > requestEnd && s.StartedAt < workDone);
        cost = new HandlerCost(scans, workDone > requestEnd ? workDone - requestEnd : TimeSpan.Zero, "measured: generated handler in the interpreter");
        return true;
    }
}
