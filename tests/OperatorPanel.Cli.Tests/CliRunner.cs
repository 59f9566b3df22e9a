namespace OperatorPanel.Cli.Tests;

/// <summary>Runs opanel in-process and captures what it prints.</summary>
internal static class CliRunner
{
    public static (int ExitCode, string Out, string Error) Run(params string[] args)
    {
        using var output = new StringWriter();
        using var error = new StringWriter();
        var logDir = Path.Combine(Path.GetTempPath(), "opanel-tests-logs");
        // Never the user's own history folder: a test that cares names its own.
        string[] history = args.Contains("--history-dir") ? [] : ["--history-dir", Path.Combine(Path.GetTempPath(), "opanel-tests-history")];
        var exit = OpanelApp.Run([.. args, "--log-dir", logDir, .. history], output, error);
        return (exit, output.ToString(), error.ToString());
    }
}
