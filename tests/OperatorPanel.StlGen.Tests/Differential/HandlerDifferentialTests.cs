using System.Text;

namespace OperatorPanel.StlGen.Tests.Differential;

/// <summary>
/// The generated handler, executed in the STL interpreter, answers random exchanges byte for byte like the reference
/// model (silence matching silence). A failure names the seed and configuration and prints the first mismatching
/// exchange with both replies; rerun with the same seed to reproduce.
/// </summary>
public sealed class HandlerDifferentialTests
{
    private const int FramesPerConfiguration = 120;
    private const int BaseSeed = 4_0000;

    public static TheoryData<int> Configurations => [.. Enumerable.Range(0, DifferentialConfigurations.All.Count)];

    [Theory]
    [MemberData(nameof(Configurations))]
    public void Handler_RandomExchanges_AnswerLikeTheReferenceModel(int index)
    {
        var options = DifferentialConfigurations.All[index];
        var seed = BaseSeed + index;
        var random = new Random(seed);
        var harness = new DifferentialHarness(options, random);
        var requests = new RandomRequests(random, harness, options.Station, options.CharTimeoutMs);
        var replies = 0;

        for (var n = 0; n < FramesPerConfiguration; n++)
        {
            var chunks = requests.Next();
            var (stl, reference) = harness.Exchange(chunks);
            if (stl != reference)
            {
                var sent = string.Join(" | ", chunks.Select(c => $"+{c.GapBefore.TotalMilliseconds}ms {Encoding.ASCII.GetString(c.Characters)}"));
                Assert.Fail($"seed {seed}, {DifferentialConfigurations.Describe(options)}, exchange {n}:\n  sent {sent}\n  stl  {Show(stl)}\n  ref  {Show(reference)}");
            }

            replies += reference.Length > 0 ? 1 : 0;
        }

        replies.Should().BeGreaterThan(FramesPerConfiguration / 4, "most exchanges are answered");
    }

    private static string Show(string s) => s.Length == 0 ? "(silence)" : s;
}
