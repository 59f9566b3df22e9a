namespace OperatorPanel.Cli.Bench;

/// <summary>
/// What one full refresh puts on the wire under one polling strategy: exchanges, characters PC→PLC and PLC→PC.
/// </summary>
internal sealed record TrafficFigures(string Name, int Frames, int RequestChars, int ReplyChars)
{
    public int TotalChars => RequestChars + ReplyChars;

    /// <summary>The characters' line time alone (no handler, delay or gap: those are the time model's, <see cref="LinkTimeModel"/>).</summary>
    public double LineMs(LineSetting line)
    {
        ArgumentNullException.ThrowIfNull(line);
        return TotalChars * line.CharacterMs;
    }
}
