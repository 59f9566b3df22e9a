using System.Collections.Immutable;
using System.CommandLine;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Transport;
using OperatorPanel.Simulator.Handlers;
using OperatorPanel.Simulator.Stl;
using OperatorPanel.Simulator.Stl.Freeport;
using OperatorPanel.Stl;
using OperatorPanel.Stl.Symbols;
using OperatorPanel.StlGen;
using OperatorPanel.StlGen.Options;
using HandlerShape = OperatorPanel.Core.Protocol.V3.HandlerShape;

namespace OperatorPanel.Cli.Commands;

/// <summary>
/// <c>opanel generate PROJECT -o DIR [--station NAME|ADDRESS] [--copy-bytes N] [--allow-stop] [--merge USER.awl] [--stats]</c>: writes the PLC handler
/// for one station (NAME-handler.awl, NAME-symbols.txt, NAME-README.txt, with --merge also NAME-merged.awl, NAME the station's name as a file name: "PLC 2" gives PLC_2-README.txt;
/// a collision with the user's program writes nothing, prints USER.awl:LINE: STLnnn ... and exits 2). CPU, station address and line settings come from
/// the project. Exit codes: 0 written, 1 bad input (project, options, files), 2 impossible handler settings (STLnnn).
/// </summary>
internal static class GenerateCommand
{
    public static Command Create(Func<ParseResult, CliContext> context)
    {
        var project = new Argument<string>("project") { Description = "The .opproj project file" };
        var output = new Option<string>("--output", "-o") { Description = "Folder for the generated files", Required = true };
        var station = new Option<string?>("--station") { Description = "Station name or address (needed when the project has several)" };
        var stats = new Option<bool>("--stats") { Description = "Print V bytes reserved, instructions and networks generated, the estimated program size beside the CPU's program memory, interrupt events, SBR/INT used, and per worst-case request (measured in the interpreter at the manual's execution times): instructions, time, longest interrupt routine, most added to one scan, scans until the slice that ends the reply's check" };
        var handler = new HandlerOptionSet();
        var merge = new Option<string?>("--merge") { Description = "A program exported from Micro/WIN (File > Export): check for collisions and write NAME-merged.awl (NAME: the station's name)" };
        var symbols = new Option<string?>("--symbols") { Description = "With --merge: the program's symbol table exported from Micro/WIN (symbol, address, comment, tab-separated), so symbolic operands are checked as their addresses" };
        var command = new Command("generate", "Generate the S7-200 handler program (.awl), symbol table and technician notes. Exit codes: 0 written, 1 bad input, 2 impossible settings")
        {
            project, output, station, stats, merge, symbols,
        };
        handler.AddTo(command);
        command.SetAction(parse =>
        {
            var cli = context(parse);
            var path = parse.GetValue(project)!;
            var loaded = ProjectFile.Load(path);
            if (!loaded.Ok)
            {
                return ProjectProblemsView.Report(cli, path, loaded, "nothing generated");
            }

            if (!GenerateSettings.TrySelectStation(loaded.Project, parse.GetValue(station), out var chosen, out var error))
            {
                return cli.Fail(ExitCodes.BadInput, error);
            }

            if (chosen.Link.Protocol == LinkProtocol.Ppi)
            {
                return cli.Fail(ExitCodes.BadInput, $"{chosen.Name} (station {chosen.Address.Address}) is on a PPI bus (\"protocol\": \"ppi\" on {chosen.Link.PortName}): "
                    + "the CPU answers PPI itself, so it needs no handler; nothing generated. Set \"protocol\": \"freeport\" to use the handler "
                    + "(change-only refresh, radio modules; docs/ppi.md)");
            }

            if (!handler.TryApply(parse, HandlerOptions.For(chosen), out var options, out error))
            {
                return cli.Fail(ExitCodes.BadInput, error);
            }

            AwlSource? userProgram = null;
            var userPath = parse.GetValue(merge);
            if (userPath is not null && !AwlFiles.TryRead(userPath, out userProgram, out error))
            {
                return cli.Fail(ExitCodes.BadInput, error);
            }

            AwlSymbolTable? table = null;
            if (parse.GetValue(symbols) is { } symbolsPath)
            {
                if (userPath is null)
                {
                    return cli.Fail(ExitCodes.BadInput, "--symbols goes with --merge: it gives the symbols of the program merged");
                }

                if (!AwlFiles.TryReadSymbols(cli, symbolsPath, out table, out error))
                {
                    return cli.Fail(ExitCodes.BadInput, error);
                }
            }

            var package = HandlerPackage.Generate(options, HandlerPackage.FileStem(chosen), userProgram, table);
            if (!package.Handler.Ok)
            {
                GenerateView.WriteRefused(cli, CompactStopOptions.Reword(package.Handler.Diagnostics, handler, parse, HandlerOptions.For(chosen), CompactStop.Who(chosen)));
                return ExitCodes.GeneratorRefused;
            }

            var warnings = package.Merge is { } merged ? GenerateMerge.Report(cli, Path.GetFileName(userPath!), merged) : [];
            return package.Ok ? Write(cli, parse.GetValue(output)!, options, package, warnings, parse.GetValue(stats)) : ExitCodes.GeneratorRefused;
        });
        return command;
    }

    private static int Write(CliContext cli, string folder, HandlerOptions options, HandlerPackage package, List<object> warnings, bool withStats)
    {
        if (!package.TryWrite(folder, out var written, out var error))
        {
            // The files saved before the one that failed are new (each save is atomic and keeps a .bak): name them.
            return cli.Fail(ExitCodes.BadInput, written.IsEmpty ? error : $"{error}; written before it: {string.Join(", ", written)}");
        }

        var (stem, result) = (package.Stem, package.Handler);
        cli.Log.Information("Generated the handler for {Stem}: {Files}", stem, written);
        var measured = ImmutableArray<MeasuredRequest>.Empty;
        var line = new LineSettings(options.BaudRate, options.Parity, options.DataBits);
        var failed = string.Empty;
        var ok = !withStats || (options.Protocol == 3
            ? V3Measurement.TryMeasure(result.AwlText, options.Cpu, options.Port, new Station(options.Station), line, options.Compact ? HandlerShape.Compact : HandlerShape.Full, out measured, out failed)
            : HandlerMeasurement.TryMeasure(result.AwlText, options.Cpu, options.Port, new Station(options.Station), line, FreeDataStart(result.Stats!), out measured, out failed));
        if (!ok)
        {
            return cli.Fail(ExitCodes.GeneratorRefused, $"the generated handler did not run in the interpreter: {failed}");
        }

        warnings.AddRange(GenerateView.WarnSize(cli, result.Stats!.Size));
        GenerateView.WriteDone(cli, [.. written], result.Stats, withStats, measured, warnings);
        return ExitCodes.Ok;
    }

    /// <summary>The measured requests read and write VB0-VB118, or the bytes just above the handler's when it sits low.</summary>
    private static int FreeDataStart(HandlerStats stats) => stats.FirstVByte >= HandlerMeasurement.DataBytes ? 0 : stats.LastVByte + 1;
}
