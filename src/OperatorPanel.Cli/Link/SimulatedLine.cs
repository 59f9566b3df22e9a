using System.Diagnostics.CodeAnalysis;
using OperatorPanel.Core.Transport;
using OperatorPanel.Simulator.Hosting;
using OperatorPanel.Simulator.Reference;
using OperatorPanel.Simulator.Stl.Freeport;
using OperatorPanel.StlGen;
using OperatorPanel.StlGen.Options;
using Serilog;

namespace OperatorPanel.Cli.Link;

/// <summary>
/// Simulated PLCs on one RS-485 bus, each optionally running the demo bottling process; what <c>opanel simulate</c>
/// serves on a serial device and what <c>--demo</c> serves in-process. <see cref="CreateStation"/> is the one place
/// the model is chosen.
/// </summary>
internal sealed class SimulatedLine
{
    private SimulatedLine(ISimulatedLine line, bool runsProcess)
    {
        Line = line;
        RunsProcess = runsProcess;
    }

    public ISimulatedLine Line { get; }

    public bool RunsProcess { get; }

    /// <summary>
    /// The stations on a line of <paramref name="serial"/>'s baud, parity and data bits; false with a message naming the
    /// station and the generator's or loader's diagnostic when the STL model cannot run one.
    /// </summary>
    public static bool TryCreate(
        IEnumerable<HandlerConfig> stations, SimulationModel model, SerialSettings serial, bool runProcess,
        [NotNullWhen(true)] out SimulatedLine? line, [NotNullWhen(false)] out string? error)
    {
        line = null;
        var bus = new BusSimulator();
        var processes = new List<DemoProcess>();
        var stl = new StlLine(LineSettings.From(serial));
        foreach (var config in stations)
        {
            if (model == SimulationModel.Reference)
            {
                var plc = new ReferencePlc(config);
                bus.Attach(plc);
                processes.AddRange(runProcess ? [new DemoProcess(plc)] : []);
            }
            else if (CreateStation(config, serial, out error) is { } station)
            {
                stl.Attach(station, runProcess);
            }
            else
            {
                error ??= $"{config.Station} cannot be simulated";
                return false;
            }
        }

        line = new SimulatedLine(model == SimulationModel.Reference ? new ReferenceLine(bus, processes) : stl, runProcess);
        error = null;
        return true;
    }

    /// <summary>Runs the line ahead by <paramref name="time"/> so the first reply already shows a running line.</summary>
    public void WarmUp(TimeSpan time) => Line.RunUntil(Line.Now + time);

    public SimulatedPlcHost HostOn(ITransport port, TimeProvider time, ILogger log) => new(port, Line, time, log);

    /// <summary>The STL model: the handler StlGen generates for the station's settings, loaded into the interpreter.</summary>
    private static StlStation? CreateStation(HandlerConfig config, SerialSettings serial, out string? error)
    {
        var generated = HandlerGenerator.Generate(new HandlerOptions
        {
            Cpu = config.Cpu,
            Port = config.Port,
            BaudRate = serial.BaudRate,
            Parity = serial.Parity,
            DataBits = serial.DataBits,
            Station = config.Station.Address,
            WriteMask = config.WriteMask,
            ReplyDelayMs = config.ReplyDelayMs,
        });
        if (!generated.Ok)
        {
            error = $"{config.Station}: the handler cannot be generated: {string.Join("; ", generated.Diagnostics)}";
            return null;
        }

        if (!StlStation.TryCreate(generated.AwlText, config.Cpu, config.Port, LineSettings.From(serial), out var station, out var loadError))
        {
            error = $"{config.Station}: the generated handler does not load in the interpreter: {loadError}";
            return null;
        }

        error = null;
        return station;
    }
}
