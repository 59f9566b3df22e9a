namespace OperatorPanel.Core.Protocol;

/// <summary>Sizes that follow from the S7-200's 255-character RCV/XMT buffers (docs/protocol.md, "Limits").</summary>
public static class ProtocolLimits
{
    /// <summary>Longest frame, '&lt;' and '&gt;' included: one RCV or XMT buffer.</summary>
    public const int MaxFrameChars = 255;

    /// <summary>Longest body in bytes: (255 - 2) characters, rounded down to whole hex pairs.</summary>
    public const int MaxBodyBytes = 126;

    /// <summary>
    /// Items in one READ request. The handler converts the 8N descriptor characters (buffer bytes 10 .. 9 + 8N) with
    /// one ATH into the 4N bytes at the end of its 256-byte buffer (256 - 4N .. 255); source and destination stay
    /// apart while 9 + 8N &lt; 256 - 4N, that is N &lt;= 20.
    /// </summary>
    public const int MaxReadItems = 20;

    /// <summary>Data bytes in the largest READ reply, the one-item case of <see cref="MaxReadDataFor"/>: (243 - 4) / 2.</summary>
    public const int MaxReadData = 119;

    /// <summary>Data bytes in one WRITE request: 126 - station, sequence, command, area, offset (2), length, block check.</summary>
    public const int MaxWriteData = 118;

    /// <summary>
    /// Data bytes a READ reply may carry for <paramref name="itemCount"/> items: floor((243 - 4N) / 2). The reply is
    /// built from buffer byte 1 on and takes 12 + 2D characters ('&lt;', STATION, SEQ, CMD, STATUS, data, BCC, '&gt;');
    /// it must end before the binary descriptors at 256 - 4N, so 12 + 2D &lt;= 255 - 4N, i.e. 2D + 4N &lt;= 243.
    /// N = 1: 119, N = 8: 105, N = 20: 81. Zero for a count outside 1 .. <see cref="MaxReadItems"/>.
    /// </summary>
    public static int MaxReadDataFor(int itemCount) =>
        itemCount is < 1 or > MaxReadItems ? 0 : (243 - (4 * itemCount)) / 2;

    /// <summary>List ids 1-4 of DEFINE LIST / READ LIST.</summary>
    public const int MaxLists = 4;

    /// <summary>
    /// Whether READ lists of (items, data bytes), defined in this order, can all be stored in one handler's buffer tail
    /// together (docs/protocol.md, "Lists"): each list's descriptors are converted by one ATH from request bytes
    /// 12 .. 11 + 8N to just below the current floor F, which must not overlap (11 + 8N &lt; F - 4N); and every list's
    /// reply (12 + 2D characters from byte 1) must end before the final floor: sum of 4N + the largest 12 + 2D &lt;= 255.
    /// </summary>
    public static bool ListsFit(IEnumerable<(int Items, int DataBytes)> lists)
    {
        ArgumentNullException.ThrowIfNull(lists);
        var all = lists.ToList();
        var floor = 256;
        foreach (var (items, _) in all)
        {
            if (items is < 1 or > MaxReadItems || 11 + (8 * items) >= floor - (4 * items))
            {
                return false;
            }

            floor -= 4 * items;
        }

        return all.Count <= MaxLists && (all.Count == 0 || all.Max(l => 12 + (2 * l.DataBytes)) <= floor - 1);
    }

    /// <summary>
    /// Whether a plain READ of <paramref name="items"/> items and <paramref name="dataBytes"/> bytes leaves lists
    /// holding <paramref name="tailBytes"/> descriptor bytes intact: its request (12 + 8N characters) ends before the
    /// floor F = 256 - tail, its descriptors ATH'd just below the floor do not overlap their source (9 + 8N &lt; F - 4N),
    /// and its reply ends before them (12 + 2D &lt;= F - 1 - 4N).
    /// </summary>
    public static bool ReadKeepsLists(int tailBytes, int items, int dataBytes)
    {
        var floor = 256 - tailBytes;
        return 12 + (8 * items) <= floor - 1 && 9 + (8 * items) < floor - (4 * items) && 12 + (2 * dataBytes) <= floor - 1 - (4 * items);
    }
}
