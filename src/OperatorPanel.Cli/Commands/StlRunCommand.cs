using System.CommandLine;
using System.Globalization;
using System.Text;
using OperatorPanel.Core.Messages;
using OperatorPanel.Simulator.Stl;
using OperatorPanel.Simulator.Stl.Run;

namespace OperatorPanel.Cli.Commands;

/// <summary>
/// <c>opanel stl run FILE.awl --cpu C [--for 5s] [--set I0.0=1[@2s]]... [--print VW0]... [--json]</c>: loads a
/// Micro/WIN export, runs it on the simulated CPU for that simulated time (scan by scan, as fast as the PC goes) with
/// those inputs, and prints each requested address as <c>ADDR value</c>. Exit 0 after the run (a CPU that went to
/// STOP is reported on stderr); 1 for a bad option or a program that cannot be loaded, each problem printed as
/// <c>FILE.awl:LINE: message</c>.
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
            Description = "Simulated time to run: 250ms, 5s, 1.5s (default 1s)",
            DefaultValueFactory = _ => "1s",
        };
        var sets = new Option<string[]>("--set")
        {
            Description = "ADDR=VALUE before the run, or ADDR=VALUE@TIME during it (I0.0=1, VW10=-5, I0.1=0@2s); repeatable",
            AllowMultipleArgumentsPerToken = false,
        };
        var prints = new Option<string[]>("--print")
        {
            Description = "Address to print after the run: Q0.0, VB10, VW10 (INT), VD10 (DINT), VD10:real, T37, T37.bit, C5, C5.bit, AC0; repeatable",
        };
        var command = new Command("run", "Run an .awl program on the simulated CPU for a simulated time and print addresses")
        {
            file, cpu, revision, duration, sets, prints,
        };
        command.SetAction(parse => Run(
            context(parse), parse.GetValue(file)!, parse.GetValue(cpu), parse.GetValue(revision), parse.GetValue(duration)!,
            parse.GetValue(sets) ?? [], parse.GetValue(prints) ?? []));
        return command;
    }

    private static int Run(CliContext cli, string path, string? cpuName, string? revisionName, string durationText, string[] setTexts, string[] printTexts)
    {
        if (!CpuOptions.TryResolve(cpuName, revisionName, out var cpu, out var cpuError))
        {
            return cli.Fail(ExitCodes.BadInput, cpuError);
        }

        if (!StlSetting.TryParseTime(durationText, out var duration))
        {
            return cli.Fail(ExitCodes.BadInput, $"--for '{durationText}': not a time (write 250ms, 5s or 1.5s, at most a day)");
        }

        var settings = new List<StlSetting>();
        foreach (var text in setTexts)
        {
            if (!StlSetting.TryParse(text, cpu, out var setting, out var error))
            {
                return cli.Fail(ExitCodes.BadInput, $"--set {error}");
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

        string awl;
        try
        {
            // Micro/WIN exports in the Windows ANSI code page: Latin-1 keeps one character per byte.
            awl = File.ReadAllText(path, Encoding.Latin1);
        }
        catch (Exception ex) when (ex is IOException or UnauthorizedAccessException or ArgumentException or NotSupportedException)
        {
            return cli.Fail(ExitCodes.BadInput, $"{path}: cannot read it: {FileProblemText.Describe(ex, path, FileAction.Read)}");
        }

        var load = StlProgramLoader.Load(awl, cpu);
        var name = Path.GetFileName(path);
        if (load.Program is null)
        {
            return Refuse(cli, name, load);
        }

        var run = new StlRun(load.Program);
        run.Run(duration, settings);
        cli.Log.Information("stl run {File} on {Cpu}: {Duration} simulated, {Scans} scans, mode {Mode}", name, cpu.Name, duration, run.Plc.Scans, run.Plc.Mode);
        return Report(cli, name, duration, run, watches);
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

    private static int Report(CliContext cli, string name, TimeSpan duration, StlRun run, List<StlWatch> watches)
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
                scans = plc.Scans,
                mode = plc.Mode.ToString(),
                stop,
                values = watches.Select(w => new { address = w.Text, value = run.Read(w) }),
            });
            return ExitCodes.Ok;
        }

        foreach (var watch in watches)
        {
            cli.Out.WriteLine(string.Create(CultureInfo.InvariantCulture, $"{watch.Text} {run.Format(watch)}"));
        }

        if (stop is not null)
        {
            cli.Error.WriteLine(stop);
        }

        return ExitCodes.Ok;
    }
}
