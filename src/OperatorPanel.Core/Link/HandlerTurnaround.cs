namespace OperatorPanel.Core.Link;

/// <summary>
/// How many scans the generated handler may take to serve a request before it starts the reply (docs/protocol.md
/// section 7). The handler does its work in bounded slices, one per scan (at most 2 loop passes: 24 characters of the
/// block check, one item checked, or one item's reply data), so the scans grow with the request's and the reply's
/// length. The bound is 4 + one scan per 12 request characters + one per 12 reply characters; StlGen's
/// HandlerCostTests prove it covers every worst-case request the handler is measured with.
/// </summary>
public static class HandlerTurnaround
{
    /// <summary>Scans of fixed steps (receive, dispatch, reply start) besides the loops.</summary>
    public const int FixedScans = 4;

    /// <summary>Characters one scan is allowed for, request and reply alike.</summary>
    public const int CharactersPerScan = 12;

    public static int ScansFor(int requestChars, int replyChars) =>
        FixedScans + Ceiling(requestChars) + Ceiling(replyChars);

    private static int Ceiling(int chars) => (Math.Max(0, chars) + CharactersPerScan - 1) / CharactersPerScan;
}
