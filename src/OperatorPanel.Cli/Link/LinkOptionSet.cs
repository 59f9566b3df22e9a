using System.CommandLine;
using System.Diagnostics.CodeAnalysis;
using System.Globalization;
using OperatorPanel.Cli.Commands;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Transport;
using OperatorPanel.Simulator.Hosting;
using OperatorPanel.StlGen;

namespace OperatorPanel.Cli.Link;

/// <summary>
/// The options every link verb (read, write, identify, stop) shares: the serial line, the station, --demo, and --cpu, which
/// checks addresses before anything is sent and, with --demo, picks the simulated CPU (default 224); or --project, which
/// gives the station's port, line settings and CPU from the project file.
/// </summary>
internal sealed class LinkOptionSet
{
    private const string DemoPort = "demo";
    private readonly SerialOptionSet _serial = new(panelSide: true);

    public Option<string> Station { get; } = new("--station")
    {
        Description = "RS-485 station address of the PLC, 1-126 (default 2, the S7-200 factory setting); with --project also the station's name",
        DefaultValueFactory = _ => "2",
    };

    public Option<bool> Demo { get; } = new("--demo")
    {
        Description = "Talk to an in-process simulated PLC of --cpu running the demo bottling process (no hardware)",
    };

    public Option<string?> Cpu { get; } = new("--cpu")
    {
        Description = "CPU model 221, 222, 224, 224XP or 226: addresses are checked against it (with --demo: the simulated CPU, default 224)",
    };

    public Option<string?> Revision { get; } = CpuOptions.Revision();

    public Option<SimulationModel> Model { get; } = ModelOption.Create();

    public Option<string?> Project { get; } = new("--project")
    {
        Description = "The .opproj project: the station's port, line settings and CPU come from it (--station ADDRESS or NAME picks the station, "
            + "needed when it has several; --device, --demo or --cpu override)",
    };

    public Option<bool> Ppi { get; } = new("--ppi")
    {
        Description = "Speak PPI, the S7-200's own protocol, instead of Freeport: no handler needed in the PLC; --baud 9600 (default), 19200 or 187500, "
            + "always 8 data bits, even parity (with --project: the station's bus says \"protocol\": \"ppi\")",
    };

    public Option<int> ScanMs { get; } = new("--scan-ms")
    {
        Description = "Longest PLC scan time in ms the reply timeout allows for (default 100); raise it for long programs: above 100 ms every scan the handler takes "
            + "for the request is allowed that long (a READ takes about 10 scans; an IDENTIFY's longest scan raises it too)",
        DefaultValueFactory = _ => 100,
    };

    public void AddTo(Command command)
    {
        _serial.AddTo(command);
        command.Options.Add(Station);
        command.Options.Add(Cpu);
        command.Options.Add(Revision);
        command.Options.Add(Demo);
        command.Options.Add(Model);
        command.Options.Add(ScanMs);
        command.Options.Add(Project);
        command.Options.Add(Ppi);
    }

    /// <summary>
    /// The target from the options alone, or with --project from the project's station (<paramref name="fromProject"/>),
    /// its port, line settings and CPU unless --device, --demo or --cpu say otherwise. False when the options are wrong,
    /// reported on <paramref name="cli"/>: a project file's problems one a line, as generate and watch list them.
    /// </summary>
    public bool TryBind(ParseResult parse, CliContext cli, [NotNullWhen(true)] out LinkTarget? target, out ProjectStation? fromProject)
    {
        fromProject = null;
        target = null;
        string? error;
        if (parse.GetValue(Project) is not { } path)
        {
            return TryBind(parse, projectStation: null, out target, out error) || Refuse(cli, error);
        }

        var loaded = ProjectFile.Load(path);
        if (!loaded.Ok)
        {
            ProjectProblemsView.Report(cli, path, loaded, "nothing sent");
            return false;
        }

        var wanted = parse.GetResult(Station) is { Implicit: false } ? parse.GetValue(Station) : null;
        if (!GenerateSettings.TrySelectStation(loaded.Project, wanted, out var station, out error)
            || !TryBind(parse, station, out target, out error))
        {
            return Refuse(cli, error);
        }

        fromProject = station;
        return true;
    }

    private static bool Refuse(CliContext cli, string error)
    {
        cli.Fail(ExitCodes.BadInput, error);
        return false;
    }

    /// <summary>
    /// The target; with <paramref name="projectStation"/> its address, its port and line settings unless --device or --demo
    /// is given, and its CPU unless --cpu is (also the CPU a --demo simulates).
    /// </summary>
    private bool TryBind(ParseResult parse, ProjectStation? projectStation, [NotNullWhen(true)] out LinkTarget? target, [NotNullWhen(false)] out string? error)
    {
        target = null;
        var demo = parse.GetValue(Demo);
        var device = parse.GetValue(_serial.Device);
        if (demo && device is not null)
        {
            error = "--demo talks to the in-process simulated PLC; leave out --device";
            return false;
        }

        if (!TryStation(parse, projectStation, out var station, out error))
        {
            return false;
        }

        SerialSettings? serial = demo || device is not null ? null : projectStation?.Link;
        var ppi = parse.GetValue(Ppi) || projectStation?.Link.Protocol == LinkProtocol.Ppi;
        if (serial is null && !(ppi
            ? _serial.TryBindPpi(parse, demo ? DemoPort : null, out serial, out error)
            : _serial.TryBind(parse, demo ? DemoPort : null, out serial, out error)))
        {
            return false;
        }

        var scanMs = parse.GetValue(ScanMs);
        if (scanMs is < 1 or > 60_000)
        {
            error = $"--scan-ms {scanMs} is outside 1-60000";
            return false;
        }

        CpuProfile? cpu = null;
        var model = parse.GetValue(Cpu) ?? (demo && projectStation is null ? "224" : null);
        if (model is not null && !CpuOptions.TryResolve(model, parse.GetValue(Revision), out cpu, out error))
        {
            return false;
        }

        cpu ??= projectStation?.Cpu;

        var notes = projectStation is null ? null : HandlerPackage.FileStem(projectStation) + "-README.txt";
        target = new LinkTarget(station, serial, cpu, demo, TimeSpan.FromMilliseconds(scanMs), parse.GetValue(Model), notes)
        {
            Compact = projectStation?.Compact ?? false,
            HandlerVFirst = projectStation?.HandlerVFirst,
        };
        error = null;
        return true;
    }

    private bool TryStation(ParseResult parse, ProjectStation? projectStation, out Core.Addressing.Station station, [NotNullWhen(false)] out string? error)
    {
        if (projectStation is not null)
        {
            (station, error) = (projectStation.Address, null);
            return true;
        }

        var text = parse.GetValue(Station) ?? "2";
        if (!int.TryParse(text, NumberStyles.AllowLeadingSign, CultureInfo.InvariantCulture, out var address))
        {
            (station, error) = (default, $"--station '{text}': a station address is a number 1-126 (a station's name works with --project)");
            return false;
        }

        return Core.Addressing.Station.TryCreate(address, out station, out error);
    }
}
