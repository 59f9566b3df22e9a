namespace OperatorPanel.Core.Protocol;

/// <summary>
/// Sizes that follow from the S7-200's 255-character RCV/XMT buffers and the v2 frame (docs/protocol-v2.md, "Limits").
/// The handler's buffer: byte 0 the character count, bytes 1-255 one frame; a request from byte 1 has '&lt;' at 1,
/// STATION 2-3, SEQ 4-5, CMD 6-7 and its payload from byte 8; a reply is built over it from byte 1.
/// </summary>
public static class ProtocolLimits
{
    /// <summary>Longest frame, '&lt;' and '&gt;' included: one RCV or XMT buffer.</summary>
    public const int MaxFrameChars = 255;

    /// <summary>Longest body in bytes: 255 - 6 = 249 characters, rounded down to whole hex pairs: 248.</summary>
    public const int MaxBodyBytes = 124;

    /// <summary>STATION SEQ CMD|16#80 STATUS REQCHECK (2): the bytes of every reply body before its payload.</summary>
    public const int ReplyHeaderBytes = 6;

    /// <summary>
    /// Items in one READ request. The handler converts the 8N descriptor characters (buffer bytes 10 .. 9 + 8N) with
    /// one ATH into the 4N bytes at the end of its 256-byte buffer (256 - 4N .. 255); source and destination stay
    /// apart while 9 + 8N &lt; 256 - 4N, that is N &lt;= 20.
    /// </summary>
    public const int MaxReadItems = 20;

    /// <summary>Data bytes in the largest READ reply, the one-item case of <see cref="MaxReadDataFor"/>: (237 - 4) / 2.</summary>
    public const int MaxReadData = 116;

    /// <summary>Data bytes in one WRITE request: 124 - station, sequence, command, area, offset (2), length.</summary>
    public const int MaxWriteData = MaxBodyBytes - 7;

    /// <summary>List ids 1-4 of DEFINE LIST, READ LIST and READ CHANGES.</summary>
    public const int MaxLists = 4;

    /// <summary>READ CHANGES: K = 16#FF marks a whole list's data; 0-127 count INDEX VALUE pairs.</summary>
    public const byte FullListMarker = 0xFF;

    /// <summary>READ CHANGES OF LISTS: K = 16#FE marks a list whose changes are not in the reply (its copy is now invalid).</summary>
    public const byte RereadListMarker = 0xFE;

    /// <summary>READ CHANGES OF LISTS: the MASK bits that name lists (bit n-1 = list n); any other bit is error 06.</summary>
    public const byte ListMaskBits = 0x0F;

    /// <summary>Most payload bytes after STATUS and REQCHECK any reply can carry: 124 - 6.</summary>
    public const int MaxReplyPayload = MaxBodyBytes - ReplyHeaderBytes;

    /// <summary>The characters of a frame whose body has <paramref name="bodyBytes"/> bytes: '&lt;', 2B, 4 check, '&gt;'.</summary>
    public static int FrameChars(int bodyBytes) => FrameCodec.OverheadChars + (2 * bodyBytes);

    /// <summary>Characters of a request with <paramref name="payloadBytes"/> after STATION SEQ CMD: 12 + 2P.</summary>
    public static int RequestChars(int payloadBytes) => FrameChars(FreeportFrame.OverheadBytes + payloadBytes);

    /// <summary>Characters of a reply with <paramref name="payloadBytes"/> after STATUS and REQCHECK: 18 + 2P.</summary>
    public static int ReplyChars(int payloadBytes) => FrameChars(ReplyHeaderBytes + payloadBytes);

    /// <summary>
    /// The longest reply a list of <paramref name="dataBytes"/> can produce: READ CHANGES answering FULL, K and D data
    /// bytes, 20 + 2D characters (READ LIST's is 18 + 2D, a pairs answer shorter still). The capacity rule of lists.
    /// </summary>
    public static int ListReplyChars(int dataBytes) => ReplyChars(1 + dataBytes);

    /// <summary>
    /// Data bytes a READ reply may carry for <paramref name="itemCount"/> items: floor((237 - 4N) / 2). The reply is
    /// built from buffer byte 1 on and takes 18 + 2D characters; it must end before the binary descriptors at
    /// 256 - 4N, so 18 + 2D &lt;= 255 - 4N, i.e. 2D + 4N &lt;= 237. N = 1: 116, N = 8: 102, N = 20: 78.
    /// Zero for a count outside 1 .. <see cref="MaxReadItems"/>.
    /// </summary>
    public static int MaxReadDataFor(int itemCount) =>
        itemCount is < 1 or > MaxReadItems ? 0 : (MaxFrameChars - ReplyChars(0) - (4 * itemCount)) / 2;

    /// <summary>
    /// Whether READ lists of (items, data bytes), defined in this order, can all be stored in one handler's buffer tail
    /// together (docs/protocol-v2.md, "Lists"): each list is a valid READ (2D + 4N &lt;= 237); its descriptors are
    /// converted by one ATH from request bytes 12 .. 11 + 8N to just below the current floor F, which must not overlap
    /// (11 + 8N &lt; F - 4N); and every list's longest reply (<see cref="ListReplyChars"/>, 20 + 2D characters from
    /// byte 1) must end before the final floor: sum of 4N + the largest 20 + 2D &lt;= 255.
    /// </summary>
    public static bool ListsFit(IEnumerable<(int Items, int DataBytes)> lists)
    {
        ArgumentNullException.ThrowIfNull(lists);
        var all = lists.ToList();
        var floor = 256;
        foreach (var (items, data) in all)
        {
            if (items is < 1 or > MaxReadItems || data < 1 || data > MaxReadDataFor(items) || 11 + (8 * items) >= floor - (4 * items))
            {
                return false;
            }

            floor -= 4 * items;
        }

        return all.Count <= MaxLists && (all.Count == 0 || all.Max(l => ListReplyChars(l.DataBytes)) <= floor - 1);
    }

    /// <summary>
    /// Whether a plain READ of <paramref name="items"/> items and <paramref name="dataBytes"/> bytes leaves lists
    /// holding <paramref name="tailBytes"/> descriptor bytes intact: its request (14 + 8N characters) ends before the
    /// floor F = 256 - tail, its descriptors ATH'd just below the floor do not overlap their source (9 + 8N &lt; F - 4N),
    /// and its reply ends before them (18 + 2D &lt;= F - 1 - 4N).
    /// </summary>
    public static bool ReadKeepsLists(int tailBytes, int items, int dataBytes)
    {
        var floor = 256 - tailBytes;
        return RequestChars(1 + (4 * items)) <= floor - 1 && 9 + (8 * items) < floor - (4 * items)
            && ReplyChars(dataBytes) <= floor - 1 - (4 * items);
    }

    /// <summary>
    /// Whether a WRITE of <paramref name="dataBytes"/> bytes leaves lists holding <paramref name="tailBytes"/> descriptor
    /// bytes intact: its request, 20 + 2L characters (the longer of request and reply), ends before the floor.
    /// </summary>
    public static bool WriteKeepsLists(int tailBytes, int dataBytes) => RequestChars(4 + dataBytes) <= 255 - tailBytes;
}
