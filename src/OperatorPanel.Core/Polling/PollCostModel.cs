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

    /// <summary>Items one READ may carry (docs/protocol.md: COUNT 1-8).</summary>
    public int MaxItemsPerFrame { get; init; } = ProtocolLimits.MaxReadItems;

    /// <summary>Data bytes one READ reply may carry (docs/protocol.md: sum of LENGTHs &lt;= 121).</summary>
    public int MaxDataPerFrame { get; init; } = ProtocolLimits.MaxReadData;

    public int RequestChars(int items) => RequestFixedChars + (ItemChars * items);

    public int ReplyChars(int dataBytes) => ReplyFixedChars + (DataByteChars * dataBytes);

    /// <summary>Request, reply and turnaround of one READ exchange.</summary>
    public int FrameCost(int items, int dataBytes) => RequestChars(items) + ReplyChars(dataBytes) + TurnaroundChars;
}
