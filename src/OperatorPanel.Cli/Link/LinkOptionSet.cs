using System.CommandLine;
using System.Diagnostics.CodeAnalysis;
using OperatorPanel.Cli.Commands;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Transport;
using OperatorPanel.Simulator.Hosting;

namespace OperatorPanel.Cli.Link;

/// <summary>
/// The options every link verb (read, write, identify) shares: the serial line, the station, --demo, and --cpu, which
/// checks addresses before anything is sent and, with --demo, picks the simulated CPU (default 224).
/// </summary>
internal sealed class LinkOptionSet
{
    private const string DemoPort = "demo";
    private readonly SerialOptionSet _serial = new(withRadio: true);

    public Option<int> Station { get; } = new("--station")
    {
        Description = "RS-485 station address of the PLC, 1-126 (default 2, the S7-200 factory setting)",
        DefaultValueFactory = _ => 2,
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

    public Option<int> ScanMs { get; } = new("--scan-ms")
    {
        Description = "Longest PLC scan time in ms the reply timeout allows for (default 100); raise it for long programs",
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
    }

    public bool TryBind(ParseResult parse, [NotNullWhen(true)] out LinkTarget? target, [NotNullWhen(false)] out string? error) =>
        TryBind(parse, projectLink: null, out target, out error);

    /// <summary>
    /// The target; with <paramref name="projectLink"/> (a project's station) its port and line settings unless --device or
    /// --demo is given.
    /// </summary>
    public bool TryBind(ParseResult parse, SerialSettings? projectLink, [NotNullWhen(true)] out LinkTarget? target, [NotNullWhen(false)] out string? error)
    {
        target = null;
        var demo = parse.GetValue(Demo);
        var device = parse.GetValue(_serial.Device);
        if (demo && device is not null)
        {
            error = "--demo talks to the in-process simulated PLC; leave out --device";
            return false;
        }

        if (!Core.Addressing.Station.TryCreate(parse.GetValue(Station), out var station, out error))
        {
            return false;
        }

        SerialSettings? serial = demo || device is not null ? null : projectLink;
        if (serial is null && !_serial.TryBind(parse, demo ? DemoPort : null, out serial, out error))
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
        var model = parse.GetValue(Cpu) ?? (demo ? "224" : null);
        if (model is not null && !CpuOptions.TryResolve(model, parse.GetValue(Revision), out cpu, out error))
        {
            return false;
        }

        target = new LinkTarget(station, serial, cpu, demo, TimeSpan.FromMilliseconds(scanMs), parse.GetValue(Model));
        error = null;
        return true;
    }
}
