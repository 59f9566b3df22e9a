namespace OperatorPanel.Cli.Bench;

/// <summary>
/// One goal of the link benchmark, judged: the measured ratio against its limit, and the numbers behind it. A goal not
/// met is a finding printed for the reader, not a failure of the benchmark (its exit code says whether it ran).
/// </summary>
internal sealed record TargetResult(string Name, bool Pass, double Ratio, string Limit, string Detail)
{
    public string Verdict => Pass ? "met" : "NOT MET";
}
