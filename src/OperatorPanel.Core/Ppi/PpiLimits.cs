using OperatorPanel.Core.Ppi.S7;

namespace OperatorPanel.Core.Ppi;

/// <summary>
/// How much one PPI exchange may carry (docs/ppi.md section 8). The PDU size is what the CPU agrees to in setup
/// communication; 240 is the size libnodave-era sources give as typical and the one we assume when no answer says
/// otherwise (no S7-200 source gives its own figure: unconfirmed). Items per job: 20, "a limit introduced by
/// Siemens PLCs" (libnodave doc/readmultiple.html); with a 240-byte PDU the request's 12 bytes per item allow 19.
/// </summary>
public sealed record PpiLimits
{
    public const int DefaultPduSize = 240;

    public static PpiLimits Default { get; } = new();

    /// <summary>Largest PDU each way, header included.</summary>
    public int PduSize { get; init; } = DefaultPduSize;

    public int MaxItems { get; init; } = 20;

    /// <summary>Most items one read job can carry: <see cref="MaxItems"/>, or fewer when the request PDU fills first.</summary>
    public int MaxReadItems => Math.Min(MaxItems, (PduSize - S7JobCodec.ItemJobOverhead) / S7Item.EncodedLength);

    /// <summary>Most data bytes one item can read: the PDU less the answer's header, parameters and item header (222 at 240).</summary>
    public int MaxReadBytes => PduSize - S7AnswerCodec.ReadAnswerOverhead;

    /// <summary>Most data bytes one item can write: the PDU less the job's header, one item address and the data header (212 at 240, as libnodave daveWriteManyBytes: PDU - 28).</summary>
    public int MaxWriteBytes => PduSize - S7JobCodec.ItemJobOverhead - S7Item.EncodedLength - 4;

    /// <summary>A gap this short between two ranges of one area is read rather than paying an item (12 request + 4 answer bytes).</summary>
    public int BridgeGap { get; init; } = 16;
}
