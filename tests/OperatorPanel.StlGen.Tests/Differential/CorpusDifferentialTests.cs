using System.Runtime.CompilerServices;
using System.Text;
using OperatorPanel.StlGen.Tests.Merge.UserPrograms;

namespace OperatorPanel.StlGen.Tests.Differential;

/// <summary>
/// The handler merged into each program of the STL corpus (tests/StlCorpus, the programs <c>opanel stl run</c> is
/// tested with) answers like the reference model while that program runs beside it: timers, counters, tables, SCR,
/// real math, interrupts and the rest of the user's instructions share the CPU with the handler. Inputs are held at 0
/// (StopWdr.awl would otherwise stop the CPU); requests keep off the bytes the program uses.
/// </summary>
public sealed class CorpusDifferentialTests
{
    /// <summary>Per program; with 14 programs the corpus adds about as many exchanges as one configuration of the handler's own run.</summary>
    internal const int ExchangesPerProgram = 60;

    private const int BaseSeed = 9_900;

    public static TheoryData<string> Programs =>
        [.. Directory.GetFiles(Folder(), "*.awl").Select(f => Path.GetFileName(f)).Where(n => n != "Refused.awl").Order(StringComparer.Ordinal)];

    [Theory]
    [MemberData(nameof(Programs))]
    public void MergedCorpusProgram_RandomExchanges_AnswerLikeTheReference(string name)
    {
        var options = UserProgram.Cpu224;
        var seed = BaseSeed + name.Length;
        var random = new Random(seed);
        var text = File.ReadAllText(Path.Combine(Folder(), name), Encoding.Latin1);
        var harness = new DifferentialHarness(options, random, text, inputsOff: true);
        var start = harness.Instructions;
        var requests = new RandomRequests(random, harness, options.Station, options.CharTimeoutMs);

        var replies = DifferentialRun.Run(harness, requests, ExchangesPerProgram, $"seed {seed}, handler merged into {name}, {DifferentialConfigurations.Describe(options)}");

        replies.Should().BeGreaterThan(ExchangesPerProgram / 4, "most exchanges are answered");
        harness.Instructions.Should().BeGreaterThan(start + (ExchangesPerProgram * 100), "the user's program ran beside the handler");
    }

    private static string Folder([CallerFilePath] string self = "") =>
        Path.GetFullPath(Path.Combine(Path.GetDirectoryName(self)!, "..", "..", "StlCorpus"));
}
