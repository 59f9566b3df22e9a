using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Core.Link;

/// <summary>
/// How many scans the generated handler may take to serve a request, up to the slice that ends its reply's check; the
/// reply's first chunks leave meanwhile, so its '&gt;' leaves no later than this bound allows (docs/protocol-v2.md
/// section 7). The handler does its work in bounded slices, one per scan (12 characters of the request's CRC frame
/// check, 14 of the reply's, 4 items checked, or 3 items' reply data), so the scans grow with the request's and the
/// reply's length. The bound is 5 + one scan per 6 request characters + one per 6 reply characters (the CRC alone
/// takes one per 12 of the request and one per 14 of the reply; the item loops of READ, DEFINE LIST and READ LIST the
/// rest); StlGen's HandlerCostTests prove it covers every worst-case request the handler is measured with, a request
/// after a cut-off frame's remains included.
/// </summary>
public static class HandlerTurnaround
{
    /// <summary>Scans of fixed steps (receive, frame check end, dispatch, reply start) besides the loops.</summary>
    public const int FixedScans = 5;

    /// <summary>Characters one scan is allowed for, request and reply alike.</summary>
    public const int CharactersPerScan = 6;

    /// <summary>
    /// Most scans READ CHANGES spends comparing a list with its copy besides its frames: one per chunk of at most
    /// <see cref="ChangeChunkBytes"/> bytes of one item, so at most one per item plus one per 8 data bytes.
    /// </summary>
    public const int ChangeComparisonScans = ProtocolLimits.MaxReadItems + ((ProtocolLimits.MaxReadData + ChangeChunkBytes - 1) / ChangeChunkBytes);

    /// <summary>Bytes of one item the handler compares with the copy in one scan at least (StlGen ChangesPart: more while its budget lasts).</summary>
    public const int ChangeChunkBytes = 8;

    /// <summary>
    /// The bound the link's reply timeout uses for <paramref name="request"/>: its frames, at the longest reply it can
    /// get, and for READ CHANGES the comparison with the copy, which depends on the list and not on the frames (for
    /// READ CHANGES OF LISTS, one comparison per list in the mask).
    /// </summary>
    public static int ScansFor(PlcRequest request, int requestChars)
    {
        ArgumentNullException.ThrowIfNull(request);
        var scans = ScansFor(requestChars, ProtocolLimits.ReplyChars(ResponseCodec.ExpectedDataBytes(request)));
        return request switch
        {
            ReadChangesRequest => scans + ChangeComparisonScans,
            ReadChangesOfListsRequest lists => scans + (lists.Lists.Count * ChangeComparisonScans),
            _ => scans,
        };
    }

    public static int ScansFor(int requestChars, int replyChars) =>
        FixedScans + Ceiling(requestChars) + Ceiling(replyChars);

    private static int Ceiling(int chars) => (Math.Max(0, chars) + CharactersPerScan - 1) / CharactersPerScan;
}
