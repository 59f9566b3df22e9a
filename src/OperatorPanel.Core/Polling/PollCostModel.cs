using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Core.Polling;

/// <summary>
/// What a READ exchange costs on the wire, in character times, so the planner can weigh "one more item" against
/// "a few more data bytes" against "one more frame". Frame layouts from docs/protocol.md: a request is
/// '&lt;' STATION SEQ CMD COUNT (AREA OFFSET LENGTH)×n BCC '&gt;' = 12 + 8n characters; a reply is
/// '&lt;' STATION SEQ CMD STATUS DATA×d BCC '&gt;' = 12 + 2d characters.
/// </summary>
public sealed record PollCostModel
{
    public static PollCostModel Default { get; } = new();

    /// <summary>'&lt;', STATION, SEQ, CMD, COUNT, BCC, '&gt;': 1 + 2 + 2 + 2 + 2 + 2 + 1.</summary>
    public int RequestFixedChars { get; init; } = 12;

    /// <summary>AREA(1) OFFSET(2) LENGTH(1) as hex: 8 characters per item.</summary>
    public int ItemChars { get; init; } = 8;

    /// <summary>'&lt;', STATION, SEQ, CMD|80, STATUS, BCC, '&gt;': 1 + 2 + 2 + 2 + 2 + 2 + 1.</summary>
    public int ReplyFixedChars { get; init; } = 12;

    /// <summary>Each data byte travels as two hex digits.</summary>
    public int DataByteChars { get; init; } = 2;

    /// <summary>
    /// Dead time of one exchange expressed in character times: the handler's reply delay, up to one scan before the
    /// cyclic part serves the request, and the PC's own turnaround. 20 ≈ 20 ms at 9600 baud 8N1 (about 1.04 ms per
    /// character): a 5 ms reply delay (seed 004's delayed reply), a 10 ms scan and some USB latency.
    /// </summary>
    public int TurnaroundChars { get; init; } = 20;

    /// <summary>Items one READ may carry (docs/protocol.md: COUNT 1-20).</summary>
    public int MaxItemsPerFrame { get; init; } = ProtocolLimits.MaxReadItems;

    /// <summary>
    /// Data bytes one READ reply may carry at most, whatever its item count (docs/protocol.md: 119, a one-item READ).
    /// A frame's real capacity is <see cref="MaxDataFor"/> its item count.
    /// </summary>
    public int MaxDataPerFrame { get; init; } = ProtocolLimits.MaxReadData;

    /// <summary>
    /// Data bytes a READ of <paramref name="items"/> items may carry: the protocol's 2D + 4N &lt;= 243 rule
    /// (<see cref="ProtocolLimits.MaxReadDataFor"/>; each item's descriptor takes buffer space from the reply),
    /// capped by <see cref="MaxDataPerFrame"/>; 0 above <see cref="MaxItemsPerFrame"/>.
    /// </summary>
    public int MaxDataFor(int items) =>
        items > MaxItemsPerFrame ? 0 : Math.Min(MaxDataPerFrame, ProtocolLimits.MaxReadDataFor(items));

    /// <summary>Whether one READ may carry <paramref name="items"/> items with <paramref name="dataBytes"/> bytes in all.</summary>
    public bool Fits(int items, int dataBytes) => items >= 1 && dataBytes <= MaxDataFor(items);

    public int RequestChars(int items) => RequestFixedChars + (ItemChars * items);

    public int ReplyChars(int dataBytes) => ReplyFixedChars + (DataByteChars * dataBytes);

    /// <summary>READ LIST: '&lt;', STATION, SEQ, CMD, LIST, BCC, '&gt;' = 12 characters whatever the list holds.</summary>
    public int ReadListRequestChars { get; init; } = 12;

    /// <summary>DEFINE LIST: '&lt;' STATION SEQ CMD LIST COUNT (AREA OFFSET LENGTH)×n BCC '&gt;' = 14 + 8n characters.</summary>
    public int DefineListRequestChars(int items) => RequestFixedChars + 2 + (ItemChars * items);

    /// <summary>
    /// What a plain READ may carry while stored lists hold <paramref name="tailBytes"/> bytes of the buffer's tail:
    /// <see cref="Fits"/>, and with a tail also <see cref="ProtocolLimits.ReadKeepsLists"/> so the READ never wipes them.
    /// </summary>
    internal FrameCapacity PlainCapacity(int tailBytes) => new(
        tailBytes,
        (items, dataBytes) => Fits(items, dataBytes) && (tailBytes == 0 || ProtocolLimits.ReadKeepsLists(tailBytes, items, dataBytes)));

    /// <summary>Request, reply and turnaround of one READ exchange.</summary>
    public int FrameCost(int items, int dataBytes) => RequestChars(items) + ReplyChars(dataBytes) + TurnaroundChars;
}
