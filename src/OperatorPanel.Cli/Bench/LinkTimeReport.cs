using System.Globalization;

namespace OperatorPanel.Cli.Bench;

/// <summary>
/// The modelled steady and idle refresh of a line on one medium, against the hex bound: the line time of the distinct
/// data bytes as two hex characters each, with no request, framing or waiting (<see cref="TrafficModels.LowerBoundAsHex"/>).
/// </summary>
internal sealed record LinkTimeReport(string Medium, LinkTimeModel Model, CycleTime Steady, CycleTime Idle, int HexBoundChars)
{
    public double HexBoundMs => HexBoundChars * Model.Line.CharacterMs;

    public double SteadyRatio => Steady.TotalMs / HexBoundMs;

    /// <summary>The one-line summary: "bench link: steady N chars, T ms, R x hex bound; idle N chars, T ms".</summary>
    public string SummaryLine => string.Create(
        CultureInfo.InvariantCulture,
        $"bench link: steady {Steady.Chars} chars, {Steady.TotalMs:0.0} ms, {SteadyRatio:0.00} x hex bound; idle {Idle.Chars} chars, {Idle.TotalMs:0.0} ms");

    public static LinkTimeReport Create(string medium, LinkTimeModel model, RefreshCycles cycles, HandlerCosts handler, BenchLine line)
    {
        ArgumentNullException.ThrowIfNull(cycles);
        ArgumentNullException.ThrowIfNull(handler);
        ArgumentNullException.ThrowIfNull(line);
        return new(
            medium,
            model,
            CycleTime.Of("steady (every value read in full)", model, cycles.Steady, handler.Steady),
            CycleTime.Of("idle (nothing changed)", model, cycles.Idle, handler.Idle),
            TrafficModels.LowerBoundAsHex(line).TotalChars);
    }
}
