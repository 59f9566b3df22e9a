using System.Collections.Immutable;
using System.Globalization;

namespace OperatorPanel.Cli.Bench;

/// <summary>
/// The targets for the reference line (issue 11, "What to build" 2): at least 8 times fewer characters than one
/// item per request on this protocol (same framing, so the ratio measures the polling strategy alone); a steady full
/// refresh at most 1.6 times the hex bound in modelled time at 9600 8N1; an idle station at most 40 characters a cycle.
/// </summary>
internal static class BenchTargets
{
    public const double MinBytesRatio = 8.0;
    public const double MaxSteadyRatio = 1.6;
    public const int MaxIdleChars = 40;

    public static ImmutableArray<TargetResult> Evaluate(TrafficFigures planned, TrafficFigures perItem, TrafficFigures seedPerItem, LinkTimeReport time)
    {
        ArgumentNullException.ThrowIfNull(planned);
        ArgumentNullException.ThrowIfNull(perItem);
        ArgumentNullException.ThrowIfNull(seedPerItem);
        ArgumentNullException.ThrowIfNull(time);
        var bytesRatio = (double)perItem.TotalChars / planned.TotalChars;
        var seedRatio = (double)seedPerItem.TotalChars / planned.TotalChars;
        var steady = time.Steady;
        var charsRatio = (double)steady.Chars / time.HexBoundChars;
        return
        [
            new TargetResult(
                "bytes on the wire",
                bytesRatio >= MinBytesRatio,
                bytesRatio,
                Invariant($">= {MinBytesRatio:0.#}x fewer than one item per request (this protocol)"),
                Invariant($"{perItem.TotalChars} / {planned.TotalChars} characters = {bytesRatio:0.00}x fewer; ")
                    + Invariant($"against the original binary protocol's frames, one item each, {seedPerItem.TotalChars} / {planned.TotalChars} = {seedRatio:0.00}x")),
            new TargetResult(
                $"steady refresh {time.Model.Line} ({time.Medium}, modelled)",
                time.SteadyRatio <= MaxSteadyRatio,
                time.SteadyRatio,
                Invariant($"<= {MaxSteadyRatio:0.0#}x the hex bound"),
                Invariant($"{steady.TotalMs:0.0} ms / {time.HexBoundMs:0.0} ms = {time.SteadyRatio:0.00}x the hex bound in time; ")
                    + Invariant($"{steady.Chars} / {time.HexBoundChars} characters = {charsRatio:0.00}x in characters alone")),
            new TargetResult(
                "idle station",
                time.Idle.Chars <= MaxIdleChars,
                time.Idle.Chars,
                Invariant($"<= {MaxIdleChars} characters per cycle"),
                Invariant($"{time.Idle.Chars} characters, {time.Idle.TotalMs:0.0} ms per idle cycle")),
        ];
    }

    private static string Invariant(FormattableString text) => text.ToString(CultureInfo.InvariantCulture);
}
