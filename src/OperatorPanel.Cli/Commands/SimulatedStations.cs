using System.CommandLine;
using System.Diagnostics.CodeAnalysis;
using OperatorPanel.Cli.Link;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Transport;
using OperatorPanel.Demo;
using OperatorPanel.Simulator.Reference;
using OperatorPanel.StlGen.Diagnostics;
using OperatorPanel.StlGen.Options;

namespace OperatorPanel.Cli.Commands;

/// <summary>
/// The PLCs <c>opanel simulate</c> serves: from --cpu and --station, or from a project's bus (--project), each station
/// with its own CPU and "allowStop", on the bus's line settings, so a line of different CPUs shares one device; each with
/// the handler options given (the same as opanel generate's).
/// </summary>
internal static class SimulatedStations
{
    /// <summary>
    /// The handler configurations and the line: with <paramref name="fromProject"/> (already checked to share one port)
    /// each station's CPU and "allowStop" and the bus's line settings, --device for the port; else --cpu and --station.
    /// The handler options (<paramref name="handler"/>: --plc-port, --copy-bytes, --writable ...) apply to every station as
    /// opanel generate applies them, checked by the generator's own check, so each station runs the handler generate
    /// would write. With --ppi no handler runs, and giving one of them is an error.
    /// </summary>
    public static bool TryBuild(
        ParseResult parse, IReadOnlyList<ProjectStation>? fromProject, Option<string> cpu, Option<string?> revision, Option<int[]> stations,
        SerialOptionSet serial, HandlerOptionSet handler, bool ppi,
        [NotNullWhen(true)] out List<HandlerConfig>? configs, [NotNullWhen(true)] out SerialSettings? settings, [NotNullWhen(false)] out string? error)
    {
        configs = null;
        settings = null;
        if (ppi && handler.Given(parse) is { } handlerOption)
        {
            error = $"--ppi runs no handler: leave out {handlerOption}";
            return false;
        }

        if (!TryLine(parse, fromProject, cpu, revision, stations, serial, ppi, out var plcs, out settings, out error))
        {
            return false;
        }

        configs = [];
        foreach (var station in plcs)
        {
            if (ppi)
            {
                configs.Add(new HandlerConfig(new Station(station.Station), station.Cpu));
                continue;
            }

            if (!handler.TryApply(parse, station, out var options, out error))
            {
                return false;
            }

            if (HandlerOptionsCheck.Check(options) is { IsEmpty: false } problems)
            {
                var who = $"station {options.Station}";
                error = $"{who}: the handler cannot be generated: {string.Join("; ", CompactStopOptions.Reword(problems, handler, parse, station, who))}";
                return false;
            }

            configs.Add(SimulatedLine.ConfigFor(options));
        }

        return true;
    }

    /// <summary>The line and, per PLC, the handler options the project or --cpu and --station fix (CPU, station, line settings, "allowStop").</summary>
    private static bool TryLine(
        ParseResult parse, IReadOnlyList<ProjectStation>? fromProject, Option<string> cpu, Option<string?> revision, Option<int[]> stations,
        SerialOptionSet serial, bool ppi,
        [NotNullWhen(true)] out List<HandlerOptions>? plcs, [NotNullWhen(true)] out SerialSettings? settings, [NotNullWhen(false)] out string? error)
    {
        plcs = null;
        settings = null;
        if (fromProject is not null)
        {
            if (new Option[] { cpu, revision, serial.Baud, serial.Parity, serial.DataBits }.FirstOrDefault(o => parse.GetResult(o) is { Implicit: false }) is { } given)
            {
                error = $"with --project each station's CPU and the bus's line settings come from the project; leave out {given.Name}";
                return false;
            }

            if (!serial.TryBind(parse, null, out var device, out error))
            {
                return false;
            }

            var link = fromProject[0].Link;
            settings = ppi
                ? device with { BaudRate = Simulator.Stl.Ppi.PpiSettings.ForLine(0, link.BaudRate).Baud, Parity = Core.Transport.Parity.Even, DataBits = 8 }
                : device with { BaudRate = link.BaudRate, Parity = link.Parity, DataBits = link.DataBits };
            plcs = [.. fromProject.Select(HandlerOptions.For)];
            return true;
        }

        if (parse.GetValue(cpu) is null || (parse.GetValue(stations) ?? []).Length == 0)
        {
            error = "give the simulated PLCs with --cpu and --station (e.g. --cpu 224 --station 2), or a project's bus with --project";
            return false;
        }

        if (!CpuOptions.TryResolve(parse.GetValue(cpu), parse.GetValue(revision), out var profile, out error)
            || !(ppi ? serial.TryBindPpi(parse, out settings, out error) : serial.TryBind(parse, null, out settings, out error)))
        {
            return false;
        }

        plcs = [];
        foreach (var address in parse.GetValue(stations) ?? [])
        {
            if (!Station.TryCreate(address, out var station, out error))
            {
                return false;
            }

            if (plcs.Any(p => p.Station == station.Address))
            {
                error = $"{station} is given twice; stations on one bus need distinct addresses";
                return false;
            }

            plcs.Add(new HandlerOptions
            {
                Cpu = profile,
                Station = station.Address,
                BaudRate = settings.BaudRate,
                Parity = settings.Parity,
                DataBits = settings.DataBits,
            });
        }

        return true;
    }

    /// <summary>
    /// The project's stations to simulate: those given with --station (each must be in the project), or all; they must
    /// share one port, since one simulate serves one bus.
    /// </summary>
    public static bool TrySelect(PanelProject project, string path, int[] wanted, [NotNullWhen(true)] out List<ProjectStation>? chosen, [NotNullWhen(false)] out string? error)
    {
        chosen = null;
        var known = string.Join(", ", project.Stations.Select(s => $"{s.Address.Address} {s.Name}"));
        var missing = wanted.FirstOrDefault(w => project.Stations.All(s => s.Address.Address != w), -1);
        if (missing != -1)
        {
            error = $"station {missing} is not in {path} (it has {known})";
            return false;
        }

        var selected = project.Stations.Where(s => wanted.Length == 0 || wanted.Contains(s.Address.Address)).ToList();
        var ports = selected.GroupBy(s => s.Link.PortName).ToList();
        if (ports.Count > 1)
        {
            var buses = string.Join("; ", ports.Select(g => $"{g.Key}: {string.Join(", ", g.Select(s => s.Address.Address))}"));
            error = $"{path} has stations on {ports.Count} ports ({buses}); one simulate serves one bus: choose its stations with --station";
            return false;
        }

        chosen = selected;
        error = null;
        return true;
    }
}
