using System.Diagnostics.CodeAnalysis;
using OperatorPanel.Core.Transport;
using OperatorPanel.Simulator.Reference;
using OperatorPanel.Simulator.Stl.Freeport;
using OperatorPanel.Simulator.Stl.Ppi;

namespace OperatorPanel.Simulator.Hosting;

/// <summary>
/// Simulated PLCs on one RS-485 bus, each optionally running the demo bottling process: what <c>opanel simulate</c>
/// serves on a serial device and what the CLI's <c>--demo</c> and the App's demo mode serve in-process. The one place
/// the <see cref="SimulationModel"/> is turned into a line.
/// </summary>
public static class SimulatedLineFactory
{
    /// <summary>
    /// The <paramref name="stations"/> on a line of <paramref name="serial"/>'s settings. For the STL model each station
    /// runs the text <paramref name="handlerSource"/> gives for it (the handler of its protocol); the reference model is
    /// Reference/V3's for protocol 3 stations (<see cref="V3ReferenceLine"/>), the v2 one for protocol 2; false with a message naming the station and the
    /// source's or the loader's reason when one cannot run (the reference model never asks the source).
    /// </summary>
    public static bool TryCreate(
        IEnumerable<HandlerConfig> stations, SimulationModel model, SerialSettings serial, bool runProcess, StlHandlerSource handlerSource,
        [NotNullWhen(true)] out ISimulatedLine? line, [NotNullWhen(false)] out string? error) =>
        TryCreate(stations, model, serial, runProcess, handlerSource, PpiMode.BesideHandler, out line, out error);

    /// <summary>
    /// As above, with the STL stations' PPI side: each answers PPI at its station number as PPI address, at the line's
    /// baud where PPI has that rate (else 9600), <paramref name="ppi"/> saying whether the handler runs beside it.
    /// </summary>
    public static bool TryCreate(
        IEnumerable<HandlerConfig> stations, SimulationModel model, SerialSettings serial, bool runProcess, StlHandlerSource handlerSource,
        PpiMode ppi, [NotNullWhen(true)] out ISimulatedLine? line, [NotNullWhen(false)] out string? error)
    {
        ArgumentNullException.ThrowIfNull(stations);
        ArgumentNullException.ThrowIfNull(serial);
        ArgumentNullException.ThrowIfNull(handlerSource);
        line = null;
        var configs = stations.ToList();
        if (model == SimulationModel.Reference && ppi == PpiMode.WithoutHandler)
        {
            error = "PPI is simulated by the STL model only (--model stl)";
            return false;
        }

        if (model == SimulationModel.Reference)
        {
            if (configs.Select(c => c.Protocol).Distinct().Count() > 1)
            {
                error = "the reference model serves one protocol per line: give every station protocol 3, or use the STL model";
                return false;
            }

            line = configs.All(c => c.Protocol == 3)
                ? new V3ReferenceLine(configs.Select(c => new Reference.V3.ReferenceHandler(c.V3SetupFor(serial))), runProcess) { CharacterTime = serial.CharacterTime }
                : CreateReference(configs, runProcess);
            error = null;
            return true;
        }

        var pcLine = LineSettings.From(serial);
        var stl = new StlLine(pcLine) { Protocol = configs.FirstOrDefault()?.Protocol ?? 2 };
        foreach (var config in configs)
        {
            var awlText = EmptyProgram.Awl;
            if (ppi == PpiMode.BesideHandler && !handlerSource(config, serial, out awlText, out var sourceError))
            {
                error = $"{config.Station}: {sourceError}";
                return false;
            }

            if (!StlStation.TryCreate(awlText, config.Cpu, config.Port, pcLine, out var station, out var loadError))
            {
                error = $"{config.Station}: the handler does not load in the interpreter: {loadError}";
                return false;
            }

            station.AttachPpi(PpiSettings.ForLine(config.Station.Address, serial.BaudRate));
            stl.Attach(station, runProcess);
        }

        line = stl;
        error = null;
        return true;
    }

    private static ReferenceLine CreateReference(IEnumerable<HandlerConfig> stations, bool runProcess)
    {
        var bus = new BusSimulator();
        var processes = new List<DemoProcess>();
        foreach (var config in stations)
        {
            var plc = new ReferencePlc(config);
            bus.Attach(plc);
            if (runProcess)
            {
                processes.Add(new DemoProcess(plc));
            }
        }

        return new ReferenceLine(bus, processes);
    }
}
