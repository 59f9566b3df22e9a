using OperatorPanel.Core.Projects;

namespace OperatorPanel.Cli.Commands;

/// <summary>
/// A project file that did not load, as every verb that needs one (generate, watch, simulate, read, write, identify, stop)
/// reports it: one problem per line in <c>project check</c>'s form (FILE: LOCATION: message), then what was not done;
/// JSON as <c>project check</c> writes it.
/// </summary>
internal static class ProjectProblemsView
{
    public static int Report(CliContext cli, string path, ProjectLoadResult loaded, string notDone)
    {
        var problems = loaded.Errors.Select(e => new ProblemView(e.Location, e.Message)).ToList();
        if (cli.Json)
        {
            cli.WriteJson(new { ok = false, file = path, problems, error = $"{path}: {Count(loaded)}; {notDone}" });
            return ExitCodes.BadInput;
        }

        foreach (var problem in problems)
        {
            cli.Error.WriteLine($"{path}: {problem.Location}: {problem.Message}");
        }

        cli.Error.WriteLine($"opanel: {path}: {Count(loaded)}; {notDone}");
        return ExitCodes.BadInput;
    }

    /// <summary>"1 problem", "7 problems", or "more than 100 problems" when the loader stopped listing them (not the lines listed).</summary>
    public static string Count(ProjectLoadResult loaded) =>
        loaded.ProblemsCut ? $"more than {ProjectLoadResult.ProblemLimit} problems" : Count(loaded.Errors.Length);

    /// <summary>"1 problem", "7 problems".</summary>
    public static string Count(int problems) => problems == 1 ? "1 problem" : $"{problems} problems";
}
