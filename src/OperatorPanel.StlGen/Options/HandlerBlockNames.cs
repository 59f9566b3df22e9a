namespace OperatorPanel.StlGen.Options;

/// <summary>
/// The names Micro/WIN shows for the handler's blocks (CALL and ATCH use them). The OP_ prefix keeps them apart from
/// the default names SBR_n / INT_n of a user's own blocks.
/// </summary>
public sealed record HandlerBlockNames
{
    /// <summary>The subroutine OB1 calls every scan: port set-up and the RUN/TERM switch.</summary>
    public string Panel { get; init; } = "OP_PANEL";

    /// <summary>Receive message complete (event 23 / 24): checks and answers a request.</summary>
    public string Receive { get; init; } = "OP_RX";

    /// <summary>Timed interrupt 0 (event 10): sends the reply after the reply delay.</summary>
    public string Delay { get; init; } = "OP_DELAY";

    /// <summary>Transmit complete (event 9 / 26): starts receiving again.</summary>
    public string Transmit { get; init; } = "OP_TX";

    public IEnumerable<string> All => [Panel, Receive, Delay, Transmit];
}
