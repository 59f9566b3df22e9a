namespace OperatorPanel.Cli.Bench;

/// <summary>
/// Dead time of one request/reply exchange besides its characters: the handler's reply delay (timed interrupt, seed 004;
/// the handler default 5 ms) and up to one PLC scan before the cyclic part serves the request (10 ms, a small program).
/// </summary>
internal sealed record ExchangeTiming(double ReplyDelayMs, double ScanMs)
{
    public static ExchangeTiming Default { get; } = new(5, 10);

    public double PerExchangeMs => ReplyDelayMs + ScanMs;
}
