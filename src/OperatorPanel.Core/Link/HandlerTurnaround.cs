namespace OperatorPanel.Core.Link;

/// <summary>
/// How many scans the generated handler may take to serve a request before it starts the reply (docs/protocol.md
/// section 7). The handler does its work in bounded slices, one per scan (at most 2 loop passes: 10 characters of
/// the CRC frame check, one item checked, or one item's reply data), so the scans grow with the request's and the
/// reply's length. The bound is 5 + one scan per 6 request characters + one per 6 reply characters (the CRC alone
/// takes one per 10; the item loops of READ, DEFINE LIST and READ LIST the rest); StlGen's HandlerCostTests prove it
/// covers every worst-case request the handler is measured with, a request after a cut-off frame's remains included.
/// </summary>
public static class HandlerTurnaround
{
    /// <summary>Scans of fixed steps (receive, frame check end, dispatch, reply start) besides the loops.</summary>
    public const int FixedScans = 5;

    /// <summary>Characters one scan is allowed for, request and reply alike.</summary>
    public const int CharactersPerScan = 6;

    public static int ScansFor(int requestChars, int replyChars) =>
        FixedScans + Ceiling(requestChars) + Ceiling(replyChars);

    private static int Ceiling(int chars) => (Math.Max(0, chars) + CharactersPerScan - 1) / CharactersPerScan;
}
