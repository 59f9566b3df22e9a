using System.Collections.Immutable;

namespace OperatorPanel.Cli.Bench;

/// <summary>
/// One request/reply exchange as the model times it: its characters on the bus and the parts of its time, from the
/// PC starting the request to the PC being allowed to start the next one.
/// </summary>
internal sealed record ExchangeTime(string Name, int RequestChars, int ReplyChars, HandlerCost Handler, ImmutableArray<TimePart> Parts)
{
    public int Chars => RequestChars + ReplyChars;

    public double TotalMs => Parts.Sum(p => p.Ms);
}
