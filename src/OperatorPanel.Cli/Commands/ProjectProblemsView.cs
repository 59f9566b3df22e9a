using OperatorPanel.Core.Projects;

namespace OperatorPanel.Cli.Commands;

/// <summary>
/// A project file that did not load, as the verbs that need one (generate, watch, stop) report it: one problem per line
/// in <c>project check</c>'s form (FILE: LOCATION: message), then what was not done; JSON as <c>project check</c> writes it.
/// </summary>
internal static class ProjectProblemsView
{
    public static int Report(CliContext cli, string path, IReadOnlyList<ProjectFileError> errors, string notDone)
    {
        var problems = errors.Select(e => new ProblemView(e.Location, e.Message)).ToList();
        if (cli.Json)
        {
            cli.WriteJson(new { ok = false, file = path, problems, error = $"{path}: {Count(problems.Count)}; {notDone}" });
            return ExitCodes.BadInput;
        }

        foreach (var problem in problems)
        {
            cli.Error.WriteLine($"{path}: {problem.Location}: {problem.Message}");
        }

        cli.Error.WriteLine($"opanel: {path}: {Count(problems.Count)}; {notDone}");
        return ExitCodes.BadInput;
    }

    private static string Count(int n) => n == 1 ? "1 problem" : $"{n} problems";
}
