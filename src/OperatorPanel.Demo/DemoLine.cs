using System.Diagnostics.CodeAnalysis;
using OperatorPanel.Core.Transport;
using OperatorPanel.Simulator.Hosting;
using OperatorPanel.Simulator.Reference;
using Serilog;

namespace OperatorPanel.Demo;

/// <summary>
/// The in-process demo line behind the App's Help > Demo and the CLI's <c>--demo</c>: simulated PLCs (the chosen <see cref="SimulationModel"/>) running the demo process on one bus, served by a
/// <see cref="Simulator.Hosting.SimulatedPlcHost"/> on real time behind an <see cref="InMemoryTransportPair"/>.
/// The panel talks to <see cref="PanelSide"/> exactly as it would to a serial port.
/// </summary>
public sealed class DemoLine : IAsyncDisposable
{
    /// <summary>The demo process starts this far in, so the first reply shows a running line with a bottle counted.</summary>
    private static readonly TimeSpan WarmUp = TimeSpan.FromSeconds(2);

    /// <summary>
    /// Added to the reply timeout (the link's scan allowance) on a demo line: the simulated PLCs run on a thread of this
    /// process, so a busy PC delays their replies by however long that thread waits for a core, which a real line never
    /// does. The App and the CLI both take it from here (<see cref="DemoLineConnector"/> hands it to the project's line).
    /// </summary>
    public static readonly TimeSpan HostAllowance = TimeSpan.FromSeconds(1);

    private readonly CancellationTokenSource _stop;
    private readonly Task _host;

    private DemoLine(ITransport panelSide, CancellationTokenSource stop, Task host)
    {
        PanelSide = panelSide;
        _stop = stop;
        _host = host;
    }

    public ITransport PanelSide { get; }

    /// <summary>Starts the line on <paramref name="serial"/>'s settings; false with the reason when a station cannot be simulated.</summary>
    public static bool TryStart(
        SerialSettings serial, IEnumerable<HandlerConfig> stations, SimulationModel model, ILogger log,
        [NotNullWhen(true)] out DemoLine? demo, [NotNullWhen(false)] out string? error)
    {
        demo = null;
        // A PPI bus's CPUs run no handler: their ports speak PPI all the time (docs/ppi.md section 11).
        var ppi = serial.Protocol == LinkProtocol.Ppi ? PpiMode.WithoutHandler : PpiMode.BesideHandler;
        if (!SimulatedLine.TryCreate(stations, model, serial, runProcess: true, ppi, out var line, out error))
        {
            return false;
        }

        line.WarmUp(WarmUp);
        var pair = new InMemoryTransportPair(TimeProvider.System, $"{serial.PortName} (demo)", $"{serial.PortName} (demo bus)");
        var host = line.HostOn(pair.BusSide, TimeProvider.System, log);
        var stop = new CancellationTokenSource();
        demo = new DemoLine(pair.PanelSide, stop, Task.Run(() => host.RunAsync(stop.Token)));
        return true;
    }

    /// <summary>Stops the simulated stations; call before the panel side is closed, or the host sees an unplugged line.</summary>
    public async ValueTask DisposeAsync()
    {
        await _stop.CancelAsync().ConfigureAwait(false);
        try
        {
            await _host.ConfigureAwait(false);
        }
        catch (OperationCanceledException) when (_stop.IsCancellationRequested)
        {
            // The host ends by cancellation; that is the normal way out.
        }

        _stop.Dispose();
    }
}
