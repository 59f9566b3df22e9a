using System.Collections.Immutable;
using System.CommandLine;
using OperatorPanel.Core.Projects;

namespace OperatorPanel.Cli.Commands;

/// <summary>
/// <c>opanel project check FILE</c>: loads a project and prints every problem as <c>FILE: location: message</c>,
/// or a summary of the line when there is none. Exit code 1 when there is any problem. Besides what stops the file from
/// loading, a problem is a setting that contradicts another though the file loads (Core ProjectChecks: a compact
/// handler with STOP, a writable tag in the handler's own V bytes or sharing bytes with a read-only tag): the panel opens
/// such a project and refuses what cannot work when it is tried.
/// </summary>
internal static class ProjectCheckCommand
{
    public static Command Create(Func<ParseResult, CliContext> context)
    {
        var file = new Argument<string>("file") { Description = "The .opproj project file to check" };
        var command = new Command("check", "Check a project file and print every problem with its location") { file };
        command.SetAction(parse =>
        {
            var cli = context(parse);
            var path = parse.GetValue(file)!;
            var result = ProjectFile.Load(path);
            var errors = result.Ok ? ProjectChecks.Problems(result.Project) : result.Errors;
            var summary = result.Ok && errors.IsEmpty ? ProjectSummaryView.From(result.Project) : null;
            var problems = errors.Select(e => new ProblemView(e.Location, e.Message)).ToList();
            if (cli.Json)
            {
                cli.WriteJson(new { ok = summary is not null, file = path, problems, project = summary });
            }
            else
            {
                WriteText(cli.Out, path, result, errors, summary);
            }

            cli.Log.Information("Checked {File}: {Count} problems", path, problems.Count);
            return summary is not null ? ExitCodes.Ok : ExitCodes.BadInput;
        });
        return command;
    }

    private static void WriteText(TextWriter o, string path, ProjectLoadResult result, ImmutableArray<ProjectFileError> errors, ProjectSummaryView? summary)
    {
        foreach (var problem in errors)
        {
            o.WriteLine($"{path}: {problem.Location}: {problem.Message}");
        }

        if (summary is null)
        {
            o.WriteLine($"{path}: {(result.Ok ? ProjectProblemsView.Count(errors.Length) : ProjectProblemsView.Count(result))}");
            return;
        }

        o.WriteLine($"{path}: ok");
        summary.WriteText(o);
    }
}

internal sealed record ProblemView(string Location, string Message);
