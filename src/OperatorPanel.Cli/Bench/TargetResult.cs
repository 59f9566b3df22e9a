namespace OperatorPanel.Cli.Bench;

/// <summary>One target of the link benchmark, judged: the measured ratio against its limit, and the numbers behind it.</summary>
internal sealed record TargetResult(string Name, bool Pass, double Ratio, string Limit, string Detail)
{
    public string Verdict => Pass ? "PASS" : "FAIL";
}
