using System.Diagnostics.CodeAnalysis;
using OperatorPanel.Core.Line;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Transport;
using OperatorPanel.Simulator.Hosting;
using OperatorPanel.Simulator.Reference;
using OperatorPanel.StlGen;
using OperatorPanel.StlGen.Options;
using Serilog;

namespace OperatorPanel.App.Services;

/// <summary>
/// Demo mode: every bus of the project gets simulated PLCs running the bottle-filler demo process behind an in-memory
/// pipe, served on real time; the panel talks to the pipe exactly as to a serial port. The PLCs run the generated
/// handler in the STL interpreter (<see cref="SimulationModel.Stl"/>, as the CLI's <c>--demo</c> does by default).
/// </summary>
public sealed class DemoLineConnector(ILogger log) : ILineConnector
{
    /// <summary>The process starts this far in, so the first values already show a running line.</summary>
    private static readonly TimeSpan WarmUp = TimeSpan.FromSeconds(2);

    /// <summary>
    /// Builds every bus's line before starting any, so a station that cannot be simulated (a handler the generator refuses
    /// for its CPU and baud) leaves nothing running; the shell shows the message as "Not connected: ...".
    /// </summary>
    public Task<LineConnection> ConnectAsync(PanelProject project, CancellationToken cancellationToken)
    {
        ArgumentNullException.ThrowIfNull(project);
        var lines = new List<(SerialSettings Serial, ISimulatedLine Line)>();
        foreach (var bus in ProjectBus.Of(project))
        {
            // The demo PLCs carry STOP where the project allows it (the sample does), so Stop can be tried on them.
            var stations = bus.Stations.Select(s => new HandlerConfig(s.Address, s.Cpu, allowStop: s.AllowStop));
            if (!SimulatedLineFactory.TryCreate(stations, SimulationModel.Stl, bus.Serial, runProcess: true, GeneratedHandler, out var line, out var error))
            {
                throw new InvalidOperationException($"the demo line cannot simulate {bus.Serial.PortName}: {error}");
            }

            lines.Add((bus.Serial, line));
        }

        var transports = new Dictionary<string, ITransport>(StringComparer.OrdinalIgnoreCase);
        var hosts = new List<Task>();
        var stop = new CancellationTokenSource();
        foreach (var (serial, line) in lines)
        {
            line.RunUntil(line.Now + WarmUp);
            var pair = new InMemoryTransportPair(TimeProvider.System, $"{serial.PortName} (demo)", $"{serial.PortName} (demo bus)");
            var host = new SimulatedPlcHost(pair.BusSide, line, TimeProvider.System, log);
            hosts.Add(Task.Run(() => host.RunAsync(stop.Token), CancellationToken.None));
            transports[serial.PortName] = pair.PanelSide;
        }

        return Task.FromResult(new LineConnection(transports, () => StopAsync(stop, hosts)));
    }

    private static async ValueTask StopAsync(CancellationTokenSource stop, List<Task> hosts)
    {
        await stop.CancelAsync();
        try
        {
            await Task.WhenAll(hosts);
        }
        catch (OperationCanceledException) when (stop.IsCancellationRequested)
        {
            // The hosts end by cancellation; that is the normal way out.
        }

        stop.Dispose();
    }

    /// <summary>The handler StlGen generates for the station: the same text Generate PLC code / opanel generate saves.</summary>
    private static bool GeneratedHandler(HandlerConfig config, SerialSettings serial, [NotNullWhen(true)] out string? awlText, [NotNullWhen(false)] out string? error) =>
        HandlerGenerator.TryGenerateAwl(
            HandlerOptions.ForLine(config.Cpu, config.Port, config.Station.Address, config.WriteMask, config.ReplyDelayMs, serial) with { AllowStop = config.AllowStop },
            out awlText,
            out error);
}
