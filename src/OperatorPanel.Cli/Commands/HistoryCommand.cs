using System.CommandLine;
using OperatorPanel.Cli.History;
using OperatorPanel.Core.Projects;
using OperatorPanel.Historian.Reading;
using OperatorPanel.Historian.Storage;

namespace OperatorPanel.Cli.Commands;

/// <summary>
/// <c>opanel history [TAG...] --project P [--demo] [--since 1h | --from T --to T] [--csv] [--json]</c>: what the project's
/// history database holds for the values, oldest first, each row the value from then on (docs/historian.md).
/// </summary>
internal static class HistoryCommand
{
    public static Command Create(Func<ParseResult, CliContext> context)
    {
        var tags = new Argument<string[]>("tag") { Description = "Symbols (TankLevel, Filler.TankLevel) or addresses (VW150); none: every recorded value", Arity = ArgumentArity.ZeroOrMore };
        var project = new Option<string>("--project") { Description = "The .opproj project file whose history is read", Required = true };
        var demo = new Option<bool>("--demo") { Description = "The history its demo line recorded (opanel watch --demo, the panel's demo) instead of the real line's" };
        var since = new Option<string?>("--since") { Description = "How far back from now: 90s, 30m, 2h, 7d (default 1h)" };
        var from = new Option<string?>("--from") { Description = "Start: 2024-01-15T08:00:00Z, or 2024-01-15 08:00 in local time" };
        var to = new Option<string?>("--to") { Description = "End (default now), written as --from" };
        var csv = new Option<bool>("--csv") { Description = "CSV for a spreadsheet: time (ISO 8601 UTC), station, symbol, address, value, number, quality" };
        var command = new Command(
            "history",
            "Print what the historian recorded of a project's values: one row per recorded change (a number moved past its deadband, "
            + "a bit or code changed, the quality changed) or periodic sample. Exit codes: 0 printed (also when nothing was recorded), "
            + "1 bad input or project problems, 2 the database could not be read")
        {
            tags, project, demo, since, from, to, csv,
        };
        command.SetAction(parse =>
        {
            var cli = context(parse);
            var path = parse.GetValue(project)!;
            var load = ProjectFile.Load(path);
            if (!load.Ok)
            {
                return ProjectProblemsView.Report(cli, path, load, "no history printed");
            }

            if (!TagArguments.TryResolve(load.Project, parse.GetValue(tags) ?? [], out var named, out var tagError))
            {
                return cli.Fail(ExitCodes.BadInput, tagError);
            }

            if (!TimeRange.TryParse(parse.GetValue(since), parse.GetValue(from), parse.GetValue(to), TimeProvider.System, out var start, out var end, out var rangeError))
            {
                return cli.Fail(ExitCodes.BadInput, rangeError);
            }

            var database = cli.History.DatabaseFor(path, parse.GetValue(demo));
            try
            {
                var reader = new HistoryReader(database);
                var histories = reader.Read([.. named.Select(n => n.Tag)], start, end);
                var view = new HistoryView(load.Project.Name, database, reader.Exists, start, end, named, histories);
                view.Print(cli, parse.GetValue(csv));
                return ExitCodes.Ok;
            }
            catch (HistoryException failure)
            {
                return cli.Fail(ExitCodes.LinkFailure, failure.Message);
            }
        });
        return command;
    }
}
