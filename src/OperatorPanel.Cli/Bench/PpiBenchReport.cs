using System.Collections.Immutable;
using System.Globalization;
using OperatorPanel.Core.Ppi;

namespace OperatorPanel.Cli.Bench;

/// <summary>
/// The PPI bench's figures for one baud rate: the plan, the refreshes simulated, and the summary line in the format of
/// the Freeport bench. PPI has no change-only read, so an idle refresh is a steady one. The hex bound is the Freeport
/// bench's yardstick, unchanged: the line's distinct data bytes as two hex characters each at 9600 8N1, so the two
/// benches' ratios compare directly.
/// </summary>
internal sealed record PpiBenchReport(
    BenchLine Line, int Baud, double ScanMs, PpiPcSide Pc, PpiReadPlan Plan, ImmutableArray<PpiRefresh> Refreshes, int HexBoundChars)
{
    public double SteadyMs => Refreshes.Average(r => r.Ms);

    public long SteadyChars => (long)Math.Round(Refreshes.Average(r => r.Chars));

    /// <summary>The hex bound's time on the reference line's Freeport setting (9600 8N1: 154.2 ms for 148 characters).</summary>
    public double HexBoundMs => HexBoundChars * LineSetting.Modeled[0].CharacterMs;

    public string SummaryLine => string.Create(
        CultureInfo.InvariantCulture,
        $"bench link: steady {SteadyChars} chars, {SteadyMs:0.0} ms, {SteadyMs / HexBoundMs:0.00} x hex bound; idle {SteadyChars} chars, {SteadyMs:0.0} ms");
}
