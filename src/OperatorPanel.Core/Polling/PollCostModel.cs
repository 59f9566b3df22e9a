using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Core.Polling;

/// <summary>
/// What an exchange costs on the wire, in character times, so the planner can weigh "one more item" against "a few
/// more data bytes" against "one more frame" against "a stored list". Frame sizes from docs/protocol-v2.md v2
/// (<see cref="ProtocolLimits.RequestChars"/>, <see cref="ProtocolLimits.ReplyChars"/>): a READ request is
/// '&lt;' STATION SEQ CMD COUNT (AREA OFFSET LENGTH)×n check '&gt;' = 14 + 8n characters, its reply
/// '&lt;' STATION SEQ CMD STATUS REQCHECK DATA×d check '&gt;' = 18 + 2d; a stored list is polled with READ CHANGES:
/// a 16-character request, a reply of 20 characters when nothing changed and 20 + 2d when the list answers FULL.
/// </summary>
public sealed record PollCostModel
{
    public static PollCostModel Default { get; } = new();

    /// <summary>A READ request without items: '&lt;', STATION, SEQ, CMD, COUNT, check, '&gt;'.</summary>
    public int RequestFixedChars { get; init; } = ProtocolLimits.RequestChars(1);

    /// <summary>AREA(1) OFFSET(2) LENGTH(1) as hex: 8 characters per item.</summary>
    public int ItemChars { get; init; } = 8;

    /// <summary>A READ reply without data: '&lt;', STATION, SEQ, CMD|80, STATUS, REQCHECK, check, '&gt;'.</summary>
    public int ReplyFixedChars { get; init; } = ProtocolLimits.ReplyChars(0);

    /// <summary>Each data byte travels as two hex digits.</summary>
    public int DataByteChars { get; init; } = 2;

    /// <summary>
    /// Dead time of one exchange expressed in character times: the handler's reply delay, up to one scan before the
    /// cyclic part serves the request, the link's minimum gap and the PC's own turnaround. 20 ≈ 20 ms at 9600 baud
    /// 8N1 (about 1.04 ms per character). The planner's weight for "one more exchange"; `opanel bench link` models
    /// the time itself.
    /// </summary>
    public int TurnaroundChars { get; init; } = 20;

    /// <summary>Items one READ may carry (docs/protocol-v2.md: COUNT 1-20).</summary>
    public int MaxItemsPerFrame { get; init; } = ProtocolLimits.MaxReadItems;

    /// <summary>
    /// Data bytes one READ reply may carry at most, whatever its item count (docs/protocol-v2.md: 116, a one-item READ).
    /// A frame's real capacity is <see cref="MaxDataFor"/> its item count.
    /// </summary>
    public int MaxDataPerFrame { get; init; } = ProtocolLimits.MaxReadData;

    /// <summary>Stored lists the planner may fill per station: 4 (ids 1-4) by default, 0 for plain READs only.</summary>
    public int MaxListsPerStation { get; init; } = ProtocolLimits.MaxLists;

    /// <summary>
    /// What one data byte of a stored list is priced at per cycle, in characters. READ CHANGES reports a byte only when
    /// it changed (4 characters as an INDEX VALUE pair, 2 inside a FULL answer) and nothing when it did not, so a
    /// list's reply lies between 20 characters (idle) and 20 + 2D (FULL). The planner prices the midpoint, 1 per byte:
    /// data in a list is worth more than the descriptors alone, but never free.
    /// </summary>
    public int ListDataByteChars { get; init; } = 1;

    /// <summary>
    /// Data bytes a READ of <paramref name="items"/> items may carry: the protocol's 2D + 4N &lt;= 237 rule
    /// (<see cref="ProtocolLimits.MaxReadDataFor"/>; each item's descriptor takes buffer space from the reply),
    /// capped by <see cref="MaxDataPerFrame"/>; 0 above <see cref="MaxItemsPerFrame"/>.
    /// </summary>
    public int MaxDataFor(int items) =>
        items > MaxItemsPerFrame ? 0 : Math.Min(MaxDataPerFrame, ProtocolLimits.MaxReadDataFor(items));

    /// <summary>Whether one READ may carry <paramref name="items"/> items with <paramref name="dataBytes"/> bytes in all.</summary>
    public bool Fits(int items, int dataBytes) => items >= 1 && dataBytes <= MaxDataFor(items);

    public int RequestChars(int items) => RequestFixedChars + (ItemChars * items);

    public int ReplyChars(int dataBytes) => ReplyFixedChars + (DataByteChars * dataBytes);

    /// <summary>READ LIST: '&lt;', STATION, SEQ, CMD, LIST, check, '&gt;', whatever the list holds.</summary>
    public int ReadListRequestChars { get; init; } = ProtocolLimits.RequestChars(1);

    /// <summary>READ CHANGES: '&lt;', STATION, SEQ, CMD, LIST, FLAGS, check, '&gt;'.</summary>
    public int ReadChangesRequestChars { get; init; } = ProtocolLimits.RequestChars(2);

    /// <summary>A READ CHANGES reply answering FULL: K = FF and the list's data (the longest a list produces).</summary>
    public int ListFullReplyChars(int dataBytes) => ListIdleReplyChars + (DataByteChars * dataBytes);

    /// <summary>A READ CHANGES reply when nothing changed: K = 0.</summary>
    public int ListIdleReplyChars { get; init; } = ProtocolLimits.ReplyChars(1);

    /// <summary>09 READ CHANGES OF LISTS: '&lt;', STATION, SEQ, CMD, MASK, check, '&gt;', whatever the lists hold.</summary>
    public int ReadChangesOfListsRequestChars { get; init; } = ProtocolLimits.RequestChars(1);

    /// <summary>A 09 reply when nothing changed in any of <paramref name="lists"/> lists: one K = 0 per list.</summary>
    public int ListsIdleReplyChars(int lists) => ReplyFixedChars + (DataByteChars * lists);

    /// <summary>DEFINE LIST: LIST, COUNT and the items' descriptors.</summary>
    public int DefineListRequestChars(int items) => ReadChangesRequestChars + (ItemChars * items);

    /// <summary>
    /// What a plain READ may carry while stored lists hold <paramref name="tailBytes"/> bytes of the buffer's tail:
    /// <see cref="Fits"/>, and with a tail also <see cref="ProtocolLimits.ReadKeepsLists"/> so the READ never wipes them.
    /// </summary>
    internal FrameCapacity PlainCapacity(int tailBytes) => new(
        tailBytes,
        (items, dataBytes) => Fits(items, dataBytes) && (tailBytes == 0 || ProtocolLimits.ReadKeepsLists(tailBytes, items, dataBytes)));

    /// <summary>Request, reply and turnaround of one plain READ exchange.</summary>
    public int FrameCost(int items, int dataBytes) => RequestChars(items) + ReplyChars(dataBytes) + TurnaroundChars;

    /// <summary>
    /// One READ CHANGES exchange of a stored list as the planner prices it: request, the idle reply, the list's data at
    /// <see cref="ListDataByteChars"/> per byte, and turnaround. No descriptors: they were sent once by DEFINE LIST.
    /// </summary>
    public int ListFrameCost(int dataBytes) =>
        ReadChangesRequestChars + ListIdleReplyChars + (ListDataByteChars * dataBytes) + TurnaroundChars;
}
