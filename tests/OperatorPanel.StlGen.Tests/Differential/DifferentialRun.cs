using System.Text;

namespace OperatorPanel.StlGen.Tests.Differential;

/// <summary>
/// Feeds seeded random exchanges to a harness and fails on the first whose replies differ, naming the seed and the
/// configuration and printing what was sent and both replies; rerun with the same seed to reproduce.
/// </summary>
internal static class DifferentialRun
{
    /// <summary>Runs <paramref name="exchanges"/> exchanges; returns how many the reference answered.</summary>
    public static int Run(DifferentialHarness harness, RandomRequests requests, int exchanges, string description)
    {
        var replies = 0;
        for (var n = 0; n < exchanges; n++)
        {
            var chunks = requests.Next();
            var (stl, reference) = harness.Exchange(chunks);
            if (stl != reference)
            {
                var sent = string.Join(" | ", chunks.Select(c => $"+{c.GapBefore.TotalMilliseconds}ms {Encoding.ASCII.GetString(c.Characters)}"));
                Assert.Fail($"{description}, exchange {n}:\n  sent {sent}\n  stl  {Show(stl)}\n  ref  {Show(reference)}");
            }

            replies += reference.Length > 0 ? 1 : 0;
        }

        return replies;
    }

    private static string Show(string s) => s.Length == 0 ? "(silence)" : s;
}
