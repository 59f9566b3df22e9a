using System.Collections.Immutable;

namespace OperatorPanel.Cli.Bench;

/// <summary>One refresh cycle timed by the <see cref="LinkTimeModel"/>: its exchanges one after the other.</summary>
internal sealed record CycleTime(string Name, ImmutableArray<ExchangeTime> Exchanges)
{
    public int Chars => Exchanges.Sum(e => e.Chars);

    public double TotalMs => Exchanges.Sum(e => e.TotalMs);

    public static CycleTime Of(string name, LinkTimeModel model, ImmutableArray<PlannedExchange> exchanges, ImmutableArray<HandlerCost> handler)
    {
        ArgumentNullException.ThrowIfNull(model);
        ArgumentOutOfRangeException.ThrowIfNotEqual(handler.Length, exchanges.Length);
        return new(name, [.. exchanges.Select((e, i) => model.Exchange(e.Name, e.RequestChars, e.ReplyChars, handler[i]))]);
    }
}
