namespace OperatorPanel.Cli.Bench;

/// <summary>
/// What one full refresh puts on the wire under one polling strategy: exchanges, characters PC→PLC and PLC→PC. A lower
/// bound has no exchanges, so no dead time either.
/// </summary>
internal sealed record TrafficFigures(string Name, int Frames, int RequestChars, int ReplyChars)
{
    public int TotalChars => RequestChars + ReplyChars;

    /// <summary>(request + reply characters) × character time + exchanges × (reply delay + scan).</summary>
    public double RefreshMs(LineSetting line, ExchangeTiming timing) =>
        (TotalChars * line.CharacterMs) + (Frames * timing.PerExchangeMs);
}
