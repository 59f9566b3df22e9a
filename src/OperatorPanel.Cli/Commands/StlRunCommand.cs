using System.CommandLine;
using System.Globalization;
using OperatorPanel.Simulator.Stl;
using OperatorPanel.Simulator.Stl.Run;
using OperatorPanel.Stl;

namespace OperatorPanel.Cli.Commands;

/// <summary>
/// <c>opanel stl run FILE.awl --cpu C [--for 5s] [--set I0.0=1[@2s]]... [--print VW0]... [--json]</c>: loads a
/// Micro/WIN export, runs it on the simulated CPU for that simulated time (scan by scan, as fast as the PC goes) with
/// those inputs, and prints each requested address as <c>ADDR value</c>: the state at the end of the last scan that
/// completed at or before --for, as the PLC shows it (outputs are written at the end of a scan). Exit 0 after the run
/// (a CPU that went to STOP is reported on stderr); 1 for a bad option or a program that cannot be loaded, each problem
/// printed as <c>FILE.awl:LINE: message</c>.
/// </summary>
internal static class StlRunCommand
{
    public static Command Create(Func<ParseResult, CliContext> context)
    {
        var file = new Argument<string>("file") { Description = "The program: a Micro/WIN STL export (.awl)" };
        var cpu = CpuOptions.Model();
        var revision = CpuOptions.Revision();
        var duration = new Option<string>("--for")
        {
            Description = "Simulated time to run: 250ms, 5s, 1.5s, 10m, 1h (default 1s); the values printed are those at the end of the last scan completed by then",
            DefaultValueFactory = _ => "1s",
        };
        var sets = new Option<string[]>("--set")
        {
            Description = "ADDR=VALUE before the run, or ADDR=VALUE@TIME during it, TIME not after --for (I0.0=1, VW10=-5, I0.1=0@2s); repeatable",
            AllowMultipleArgumentsPerToken = false,
        };
        var prints = new Option<string[]>("--print")
        {
            Description = "Address to print, as at the end of the last complete scan: Q0.0, VB10, VW10 (INT), VD10 (DINT), VD10:real, T37, T37.bit, C5, C5.bit, AC0; repeatable",
        };
        var strict = new Option<bool>("--strict")
        {
            Description = "Refuse instructions the simulator treats as doing nothing (HDEF, HSC, PLS) and interrupt events it never raises, instead of warning",
        };
        var symbols = new Option<string?>("--symbols")
        {
            Description = "The program's symbol table exported from Micro/WIN (tab-separated: symbol, address, comment): symbolic operands become its addresses",
        };
        var command = new Command("run", "Run an .awl program on the simulated CPU for a simulated time and print addresses as they are at the end of the last complete scan")
        {
            file, cpu, revision, duration, sets, prints, strict, symbols,
        };
        command.SetAction(parse => Run(
            context(parse), parse.GetValue(file)!, parse.GetValue(cpu), parse.GetValue(revision), parse.GetValue(duration)!,
            parse.GetValue(sets) ?? [], parse.GetValue(prints) ?? [], new StlLoadOptions { Strict = parse.GetValue(strict) }, parse.GetValue(symbols)));
        return command;
    }

    private static int Run(
        CliContext cli, string path, string? cpuName, string? revisionName, string durationText, string[] setTexts, string[] printTexts,
        StlLoadOptions options, string? symbolsPath)
    {
        if (!CpuOptions.TryResolve(cpuName, revisionName, out var cpu, out var cpuError))
        {
            return cli.Fail(ExitCodes.BadInput, cpuError);
        }

        if (!StlSetting.TryParseTime(durationText, out var duration))
        {
            return cli.Fail(ExitCodes.BadInput, $"--for '{durationText}': not a time (write 250ms, 5s, 1.5s, 10m or 1h, at most a day)");
        }

        var settings = new List<StlSetting>();
        foreach (var text in setTexts)
        {
            if (!StlSetting.TryParse(text, cpu, out var setting, out var error))
            {
                return cli.Fail(ExitCodes.BadInput, $"--set {error}");
            }

            if (setting.At > duration)
            {
                return cli.Fail(ExitCodes.BadInput, string.Create(CultureInfo.InvariantCulture,
                    $"--set '{text}': {setting.At.TotalMilliseconds} ms is after --for {durationText}: the run ends before it (set it earlier or run longer)"));
            }

            settings.Add(setting);
        }

        var watches = new List<StlWatch>();
        foreach (var text in printTexts)
        {
            if (!StlWatch.TryParse(text, cpu, out var watch, out var error))
            {
                return cli.Fail(ExitCodes.BadInput, $"--print {error}");
            }

            watches.Add(watch);
        }

        if (!AwlFiles.TryRead(path, out var source, out var readError))
        {
            return cli.Fail(ExitCodes.BadInput, readError);
        }

        if (symbolsPath is not null)
        {
            if (!AwlFiles.TryReadSymbols(cli, symbolsPath, out var table, out readError))
            {
                return cli.Fail(ExitCodes.BadInput, readError);
            }

            options = options with { Symbols = table };
        }

        var load = StlProgramLoader.Load(source.Text, cpu, options);
        var name = Path.GetFileName(path);
        if (load.Program is null)
        {
            return Refuse(cli, name, load);
        }

        var run = new StlRun(load.Program);
        run.Run(duration, settings);
        cli.Log.Information("stl run {File} on {Cpu}: {Duration} simulated, {Scans} scans, mode {Mode}", name, cpu.Name, duration, run.Plc.Scans, run.Plc.Mode);
        return Report(cli, name, duration, run, watches, load.Warnings);
    }

    private static int Refuse(CliContext cli, string name, StlLoadResult load)
    {
        if (cli.Json)
        {
            cli.WriteJson(new { ok = false, diagnostics = load.Diagnostics.Select(d => new { file = name, line = d.Line, message = d.Message }) });
        }
        else
        {
            foreach (var diagnostic in load.Diagnostics)
            {
                cli.Error.WriteLine($"{name}:{diagnostic.Line}: {diagnostic.Message}");
            }

            cli.Error.WriteLine($"opanel: {name} cannot run on the simulated CPU ({load.Diagnostics.Length} problem(s))");
        }

        return ExitCodes.BadInput;
    }

    private static int Report(CliContext cli, string name, TimeSpan duration, StlRun run, List<StlWatch> watches, IReadOnlyList<AwlDiagnostic> warnings)
    {
        var plc = run.Plc;
        var stop = plc.Fault is { } fault ? $"{name}:{fault.Line}: the CPU went to STOP ({fault.Code} in {fault.Block}): {fault.Message}" : null;
        if (cli.Json)
        {
            cli.WriteJson(new
            {
                ok = true,
                file = name,
                simulatedMs = duration.TotalMilliseconds,
                stateAtMs = run.ReadAt?.TotalMilliseconds,
                noScanCompleted = run.NoScanCompleted,
                warnings = warnings.Select(w => new { file = name, line = w.Line, message = w.Message }),
                scans = plc.Scans,
                mode = plc.Mode.ToString(),
                stop,
                values = watches.Select(w => new { address = w.Text, value = run.Read(w) }),
            });
            return ExitCodes.Ok;
        }

        foreach (var warning in warnings)
        {
            cli.Error.WriteLine($"{name}:{warning.Line}: warning: {warning.Message}");
        }

        foreach (var watch in watches)
        {
            cli.Out.WriteLine(string.Create(CultureInfo.InvariantCulture, $"{watch.Text} {run.Format(watch)}"));
        }

        if (stop is not null)
        {
            cli.Error.WriteLine(stop);
        }

        if (run.NoScanCompleted)
        {
            cli.Error.WriteLine($"opanel: warning: no scan of {name} completed within --for; the values are those at the end of the run");
        }

        return ExitCodes.Ok;
    }
}
