using System.CommandLine;
using OperatorPanel.Cli.Bench;
using OperatorPanel.Cli.Link;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Simulator.Hosting;
using OperatorPanel.Simulator.Reference;
using OperatorPanel.Simulator.Reference.V3;
using OperatorPanel.Simulator.Soak;
using OperatorPanel.Simulator.Stl.Freeport;
using OperatorPanel.StlGen;
using OperatorPanel.StlGen.Options;

namespace OperatorPanel.Cli.Commands;

/// <summary>
/// <c>opanel soak [--minutes N] [--profile flips|mixed|clean] [--seed N] [--baud B] [--lines N] [--model stl|reference] [--scan-ms M]</c>: the long soak of docs/soak.md.
/// The panel stack watches and writes the ends of every area Freeport reaches (<see cref="SoakRegion.AreaEnds"/>) of the generated
/// CPU 226 handler in the STL interpreter (or the reference model) through a noisy-line proxy between two socat pty pairs, while the
/// field changes the last I bytes, and the judge prints the figures per profile (both noisy profiles unless one is
/// named). Exit 0 when the must-be-0 figures are 0, 2 when one is not, 1 for a bad option or a missing socat.
/// </summary>
internal static class SoakCommand
{
    private static readonly CpuProfile Cpu = CpuProfiles.For(CpuModel.Cpu226);

    public static Command Create(Func<ParseResult, CliContext> context)
    {
        var minutes = new Option<double>("--minutes") { Description = "Minutes per profile (default 1)", DefaultValueFactory = _ => 1 };
        var profile = new Option<string?>("--profile") { Description = "flips (1% bits), mixed (0.5% bits, 0.5% characters, 5% frames) or clean; default flips and mixed" };
        var seed = new Option<int>("--seed") { Description = "Seed of the faults and of the panel's choices (default 11)", DefaultValueFactory = _ => 11 };
        var baud = new Option<int>("--baud") { Description = "Baud rate of the line (default 19200)", DefaultValueFactory = _ => 19200 };
        var lines = new Option<int>("--lines")
        {
            Description = "Lines run side by side, each with its own pty pairs, PLC and seed (seed, seed+1, ...), counted together (default 1)",
            DefaultValueFactory = _ => 1,
        };
        var model = ModelOption.Create();
        var scan = new Option<double>("--scan-ms")
        {
            Description = "With the generated handler: the machine program's time per scan beside the handler, in ms (default 5, as bench link assumes)",
            DefaultValueFactory = _ => 5,
        };
        var command = new Command("soak", "Soak the link on a noisy simulated line and judge it against what the PLC executed") { minutes, profile, seed, baud, lines, model, scan };
        command.SetAction(async (parse, cancellationToken) =>
        {
            var cli = context(parse);
            var length = parse.GetValue(minutes);
            if (!(length > 0 && length <= 24 * 60))
            {
                return cli.Fail(ExitCodes.BadInput, $"--minutes {length}: give more than 0 and at most 1440");
            }

            var scanMs = parse.GetValue(scan);
            if (!(scanMs >= 0 && scanMs <= 400))
            {
                return cli.Fail(ExitCodes.BadInput, $"--scan-ms {scanMs}: give 0-400 ms (the S7-200 watchdog ends a scan at 500 ms)");
            }

            var lineCount = parse.GetValue(lines);
            if (lineCount is < 1 or > 16)
            {
                return cli.Fail(ExitCodes.BadInput, $"--lines {lineCount}: give 1 to 16");
            }

            IReadOnlyList<LineFaults> profiles = [LineFaults.Flips, LineFaults.Mixed];
            if (parse.GetValue(profile) is { } name)
            {
                if (!LineFaults.TryFind(name, out var one, out var error))
                {
                    return cli.Fail(ExitCodes.BadInput, $"--profile: {error}");
                }

                profiles = [one];
            }

            if (SocatPty.Find() is not { } socat)
            {
                return cli.Fail(ExitCodes.BadInput, "socat not found on PATH: the soak runs over socat pty pairs (Debian package socat)");
            }

            var allHold = true;
            foreach (var faults in profiles)
            {
                var runs = await Task.WhenAll(Enumerable.Range(0, lineCount).Select(i =>
                    RunAsync(socat, parse.GetValue(model), faults, parse.GetValue(seed) + i, parse.GetValue(baud), TimeSpan.FromMilliseconds(scanMs), TimeSpan.FromMinutes(length), cli, cancellationToken)));
                if (runs.Any(r => r is null))
                {
                    return ExitCodes.BadInput;
                }

                var figures = SoakFigures.Combine([.. runs.Select(r => r!)]);

                allHold &= figures.ZerosHold;
                if (cli.Json)
                {
                    cli.WriteJsonLine(figures);
                }
                else
                {
                    foreach (var text in figures.Text())
                    {
                        cli.Out.WriteLine(text);
                    }
                }
            }

            return allHold ? ExitCodes.Ok : ExitCodes.LinkFailure;
        });
        return command;
    }

    private static async Task<SoakFigures?> RunAsync(
        string socat, SimulationModel model, LineFaults faults, int seed, int baud, TimeSpan userProgram, TimeSpan duration, CliContext cli, CancellationToken cancellationToken)
    {
        if (!TryCreatePlc(model, baud, userProgram, out var plc, out var error))
        {
            cli.Fail(ExitCodes.BadInput, error);
            return null;
        }

        using var panelPair = await SocatPty.StartAsync(socat, TimeProvider.System, cancellationToken);
        using var plcPair = await SocatPty.StartAsync(socat, TimeProvider.System, cancellationToken);
        return await SoakSession.RunAsync(
            new SoakSetup
            {
                PanelPort = panelPair.PanelEnd,
                ProxyPanelSide = panelPair.PlcEnd,
                ProxyPlcSide = plcPair.PanelEnd,
                PlcPort = plcPair.PlcEnd,
                Baud = baud,
                Faults = faults,
                Seed = seed,
                Duration = duration,
                Station = new Station(2),
                Cpu = Cpu,
                Line = plc.Line,
                Memory = plc.Memory,
                HandlerFirstByte = plc.HandlerFirstByte,
                Inputs = plc.Inputs,
            },
            TimeProvider.System,
            cli.Log,
            cancellationToken);
    }

    /// <summary>Station 2 on a line of its own: the generated handler in the interpreter, or the reference model.</summary>
    private static bool TryCreatePlc(SimulationModel model, int baud, TimeSpan userProgram, out (ISimulatedLine Line, PlcMemory Memory, int HandlerFirstByte, byte[] Inputs) plc, out string error)
    {
        plc = default;
        error = string.Empty;
        var options = new HandlerOptions { Cpu = Cpu, Station = 2, BaudRate = baud, Protocol = 3 };
        if (model == SimulationModel.Reference)
        {
            var reference = new ReferenceHandler(new HandlerSetup(
                new Station(2), Cpu, endTimeoutMs: (byte)options.EffectiveEndTimeoutMs, vFirst: options.EffectiveV3First));
            // The reference model reads I itself: the field sets it there.
            plc = (new V3ReferenceLine([reference]), reference.Memory, reference.Setup.VFirst, reference.Memory.I);
            return true;
        }

        var generated = HandlerGenerator.Generate(options);
        if (!generated.Ok)
        {
            error = $"the handler for {baud} baud cannot be generated: {string.Join("; ", generated.Diagnostics)}";
            return false;
        }

        var settings = new LineSettings(baud, Core.Transport.Parity.None, 8);
        if (!StlStation.TryCreate(generated.AwlText, Cpu, 0, settings, out var station, out var loadError))
        {
            error = $"the handler does not load in the interpreter: {loadError}";
            return false;
        }

        // The machine's own program runs beside the handler: the handler's reply then leaves in chunks over several scans.
        station.Plc.UserProgramTime = userProgram;
        var line = new StlLine(settings);
        line.Attach(station, runProcess: false);
        // The interpreter's CPU copies its physical inputs into I at each scan: the field sets those.
        plc = (line, station.Memory, options.EffectiveV3First, station.Plc.InputImage);
        return true;
    }
}
