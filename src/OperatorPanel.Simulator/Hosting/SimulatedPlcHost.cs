using OperatorPanel.Core.Transport;
using OperatorPanel.Simulator.Reference;
using Serilog;

namespace OperatorPanel.Simulator.Hosting;

/// <summary>
/// Puts a simulated line (<see cref="ISimulatedLine"/>: the reference model or the generated .awl in the interpreter) on
/// a byte pipe: a serial device (`opanel simulate`), or one end of an in-memory pair (demo mode, tests). Simulated time
/// follows the TimeProvider: each turn the line runs up to now, the PC's bytes go on the line at now, and every
/// character the stations finished sending by now is written to the pipe.
/// </summary>
public sealed class SimulatedPlcHost
{
    /// <summary>How long one read waits before the line is advanced anyway: a reply leaves at most this late.</summary>
    private static readonly TimeSpan IdlePoll = TimeSpan.FromMilliseconds(2);

    private readonly ITransport _port;
    private readonly ISimulatedLine _line;
    private readonly TimeProvider _time;
    private readonly ILogger _log;

    public SimulatedPlcHost(ITransport port, ISimulatedLine line, TimeProvider time, ILogger? log = null)
    {
        ArgumentNullException.ThrowIfNull(port);
        ArgumentNullException.ThrowIfNull(line);
        ArgumentNullException.ThrowIfNull(time);
        _port = port;
        _line = line;
        _time = time;
        _log = (log ?? Serilog.Core.Logger.None).ForContext<SimulatedPlcHost>();
    }

    /// <summary>The reference model's stations on <paramref name="bus"/>, with their demo processes.</summary>
    public SimulatedPlcHost(ITransport port, BusSimulator bus, IReadOnlyList<DemoProcess> processes, TimeProvider time, ILogger? log = null)
        : this(port, new ReferenceLine(bus, processes), time, log)
    {
    }

    public ISimulatedLine Line => _line;

    /// <summary>Frames answered since start.</summary>
    public int Replies => _line.Replies;

    /// <summary>Serves the line until cancelled. A failing port ends the run with its exception.</summary>
    public async Task RunAsync(CancellationToken cancellationToken)
    {
        if (!_port.IsOpen)
        {
            await _port.OpenAsync(cancellationToken).ConfigureAwait(false);
        }

        var buffer = new byte[512];
        var origin = _line.Now;
        var start = _time.GetTimestamp();
        while (!cancellationToken.IsCancellationRequested)
        {
            var wait = _line.NextOutput is { } due && due - _line.Now < IdlePoll ? Max(due - _line.Now, TimeSpan.FromTicks(1)) : IdlePoll;
            var count = await _port.ReadAsync(buffer, wait, cancellationToken).ConfigureAwait(false);
            _line.RunUntil(origin + _time.GetElapsedTime(start));
            if (count > 0)
            {
                _line.Deliver(buffer.AsSpan(0, count));
            }

            var sent = _line.TakeTransmitted();
            if (sent.Length > 0)
            {
                await _port.WriteAsync(sent, cancellationToken).ConfigureAwait(false);
                _log.Debug("Sent {Chars} characters at {Time}", sent.Length, _line.Now);
            }
        }
    }

    private static TimeSpan Max(TimeSpan a, TimeSpan b) => a > b ? a : b;
}
