using OperatorPanel.Core.Transport;
using OperatorPanel.Simulator.Reference;
using Serilog;

namespace OperatorPanel.Simulator.Hosting;

/// <summary>
/// Puts simulated PLCs on a byte pipe: a serial device (`opanel simulate`), or one end of an in-memory pair (demo mode,
/// tests). Every received byte goes to every station on the bus; a reply leaves after that station's reply delay, as the
/// handler's timed interrupt would send it. The demo processes run on the same clock.
/// </summary>
public sealed class SimulatedPlcHost
{
    /// <summary>How long one read waits before the processes are advanced anyway.</summary>
    private static readonly TimeSpan IdlePoll = TimeSpan.FromMilliseconds(10);

    private readonly ITransport _port;
    private readonly BusSimulator _bus;
    private readonly IReadOnlyList<DemoProcess> _processes;
    private readonly TimeProvider _time;
    private readonly ILogger _log;

    public SimulatedPlcHost(ITransport port, BusSimulator bus, IReadOnlyList<DemoProcess> processes, TimeProvider time, ILogger? log = null)
    {
        ArgumentNullException.ThrowIfNull(port);
        ArgumentNullException.ThrowIfNull(bus);
        ArgumentNullException.ThrowIfNull(processes);
        ArgumentNullException.ThrowIfNull(time);
        _port = port;
        _bus = bus;
        _processes = processes;
        _time = time;
        _log = (log ?? Serilog.Core.Logger.None).ForContext<SimulatedPlcHost>();
    }

    /// <summary>Frames answered since start.</summary>
    public int Replies { get; private set; }

    /// <summary>Serves the bus until cancelled. A failing port ends the run with its exception.</summary>
    public async Task RunAsync(CancellationToken cancellationToken)
    {
        if (!_port.IsOpen)
        {
            await _port.OpenAsync(cancellationToken).ConfigureAwait(false);
        }

        var buffer = new byte[512];
        var last = _time.GetTimestamp();
        while (!cancellationToken.IsCancellationRequested)
        {
            var count = await _port.ReadAsync(buffer, IdlePoll, cancellationToken).ConfigureAwait(false);
            last = AdvanceProcesses(last);
            if (count > 0)
            {
                await ServeAsync(buffer.AsMemory(0, count), cancellationToken).ConfigureAwait(false);
            }
        }
    }

    private async Task ServeAsync(ReadOnlyMemory<byte> received, CancellationToken cancellationToken)
    {
        foreach (var station in _bus.Ports)
        {
            foreach (var reply in station.Feed(received.Span))
            {
                await Task.Delay(station.ReplyDelay, _time, cancellationToken).ConfigureAwait(false);
                await _port.WriteAsync(reply, cancellationToken).ConfigureAwait(false);
                Replies++;
                _log.Debug("{Station} answered {Chars} characters", station.Plc.Config.Station, reply.Length);
            }
        }
    }

    private long AdvanceProcesses(long since)
    {
        var now = _time.GetTimestamp();
        var elapsed = _time.GetElapsedTime(since, now);
        foreach (var process in _processes)
        {
            process.Advance(elapsed);
        }

        return now;
    }
}
