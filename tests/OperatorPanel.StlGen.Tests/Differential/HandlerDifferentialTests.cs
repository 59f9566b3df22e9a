namespace OperatorPanel.StlGen.Tests.Differential;

/// <summary>
/// The generated handler, executed in the STL interpreter, answers random exchanges byte for byte like the reference
/// model (silence matching silence). A failure names the seed and configuration and prints the first mismatching
/// exchange with both replies; rerun with the same seed to reproduce.
/// </summary>
public sealed class HandlerDifferentialTests
{
    /// <summary>20 configurations x 600 = 12,000 exchanges, about 20 s of the project's ~40 s budget on 2 cores.</summary>
    internal const int ExchangesPerConfiguration = 600;

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

        var replies = DifferentialRun.Run(harness, requests, ExchangesPerConfiguration, $"seed {seed}, {DifferentialConfigurations.Describe(options)}");

        replies.Should().BeGreaterThan(ExchangesPerConfiguration / 4, "most exchanges are answered");
    }
}
