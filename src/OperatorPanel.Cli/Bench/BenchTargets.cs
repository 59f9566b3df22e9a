using System.Collections.Immutable;
using System.Globalization;

namespace OperatorPanel.Cli.Bench;

/// <summary>
/// The targets for a full refresh of the reference line: at least 8 times fewer characters than one item per
/// request on this protocol (same framing, so the ratio measures the polling strategy alone), and a refresh time at
/// 9600 baud within 2.5 times the time the bare data bytes take as hex (the characters this protocol cannot avoid).
/// </summary>
internal static class BenchTargets
{
    public const double MinBytesRatio = 8.0;
    public const double MaxTimeRatio = 2.5;
    public const int TimeTargetBaud = 9600;

    public static ImmutableArray<TargetResult> Evaluate(
        TrafficFigures planned,
        TrafficFigures perItem,
        TrafficFigures seedPerItem,
        TrafficFigures lowerHex,
        TrafficFigures lowerBinary,
        ExchangeTiming timing)
    {
        ArgumentNullException.ThrowIfNull(planned);
        ArgumentNullException.ThrowIfNull(perItem);
        ArgumentNullException.ThrowIfNull(seedPerItem);
        ArgumentNullException.ThrowIfNull(lowerHex);
        ArgumentNullException.ThrowIfNull(lowerBinary);
        ArgumentNullException.ThrowIfNull(timing);
        var results = ImmutableArray.CreateBuilder<TargetResult>();
        var bytesRatio = (double)perItem.TotalChars / planned.TotalChars;
        var seedRatio = (double)seedPerItem.TotalChars / planned.TotalChars;
        results.Add(new TargetResult(
            "bytes on the wire",
            bytesRatio >= MinBytesRatio,
            bytesRatio,
            Invariant($">= {MinBytesRatio:0.#}x fewer than one item per request (this protocol)"),
            Invariant($"{perItem.TotalChars} / {planned.TotalChars} characters = {bytesRatio:0.00}x fewer; ")
                + Invariant($"against the seed paper's own frames {seedPerItem.TotalChars} / {planned.TotalChars} = {seedRatio:0.00}x ")
                + "(its binary frames are not safely framed: a data byte equal to '>' ends them, which is why this protocol "
                + "sends hex and pays 2 characters per data byte)"));

        foreach (var line in LineSetting.Modeled.Where(l => l.Baud == TimeTargetBaud))
        {
            var time = planned.RefreshMs(line, timing);
            var hex = lowerHex.RefreshMs(line, timing);
            var binary = lowerBinary.RefreshMs(line, timing);
            var ratio = time / hex;
            results.Add(new TargetResult(
                $"refresh time {line}",
                ratio <= MaxTimeRatio,
                ratio,
                Invariant($"<= {MaxTimeRatio:0.0#}x the hex lower bound"),
                Invariant($"{time:0.0} ms / {hex:0.0} ms = {ratio:0.00}x the hex lower bound; ")
                    + Invariant($"{time / binary:0.00}x the binary lower bound {binary:0.0} ms (hex encoding, required by the protocol, alone doubles it)")));
        }

        return results.ToImmutable();
    }

    private static string Invariant(FormattableString text) => text.ToString(CultureInfo.InvariantCulture);
}
