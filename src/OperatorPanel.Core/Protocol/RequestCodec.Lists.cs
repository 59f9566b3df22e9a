using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Core.Protocol;

/// <summary>The station side of DEFINE LIST, READ LIST, READ CHANGES and STOP (docs/protocol-v2.md, "Processing order", step 6).</summary>
public static partial class RequestCodec
{
    /// <summary>
    /// Body &gt;= 5 bytes and COUNT 1-20 else 04; body == 5 + 4 x COUNT else 04; LIST not 1-4 -> 06; then the items
    /// exactly like a READ. The tail capacity check is the station's (it needs the stored lists).
    /// </summary>
    private static ProtocolError ParseDefineList(Station station, FreeportFrame frame, ReadOnlySpan<byte> p, IRequestTarget? target, out PlcRequest request)
    {
        request = null!;
        if (frame.BodyBytes < 5 || p[1] is < 1 or > ProtocolLimits.MaxReadItems || frame.BodyBytes != 5 + (4 * p[1]))
        {
            return ProtocolError.BadLength;
        }

        if (p[0] is < 1 or > ProtocolLimits.MaxLists)
        {
            return ProtocolError.BadParameter;
        }

        var error = ParseItems(p[2..], p[1], target, out var items);
        if (error == ProtocolError.None)
        {
            request = new DefineListRequest(station, frame.Sequence, p[0], items);
        }

        return error;
    }

    /// <summary>
    /// Body == 4 bytes else 04. Any LIST byte parses: one outside 1-4 is simply never defined, so the station answers 07.
    /// </summary>
    private static ProtocolError ParseReadList(Station station, FreeportFrame frame, ReadOnlySpan<byte> p, out PlcRequest request)
    {
        request = null!;
        if (frame.BodyBytes != 4)
        {
            return ProtocolError.BadLength;
        }

        request = new ReadListRequest(station, frame.Sequence, p[0]);
        return ProtocolError.None;
    }

    /// <summary>
    /// Body == 5 bytes else 04; FLAGS with a bit other than FULL -> 06. Any LIST byte parses, as for READ LIST: one that
    /// is not defined (or outside 1-4) is the station's 07.
    /// </summary>
    private static ProtocolError ParseReadChanges(Station station, FreeportFrame frame, ReadOnlySpan<byte> p, out PlcRequest request)
    {
        request = null!;
        if (frame.BodyBytes != 5)
        {
            return ProtocolError.BadLength;
        }

        if ((p[1] & ~ReadChangesFlags.Full) != 0)
        {
            return ProtocolError.BadParameter;
        }

        request = new ReadChangesRequest(station, frame.Sequence, p[0], p[1] == ReadChangesFlags.Full);
        return ProtocolError.None;
    }

    /// <summary>
    /// Body == 4 bytes else 04; MASK 0 or with a bit outside 0-3 -> 06. Whether every list in the mask is defined (else
    /// 07) is the station's.
    /// </summary>
    private static ProtocolError ParseReadChangesOfLists(Station station, FreeportFrame frame, ReadOnlySpan<byte> p, out PlcRequest request)
    {
        request = null!;
        if (frame.BodyBytes != 4)
        {
            return ProtocolError.BadLength;
        }

        if (p[0] == 0 || (p[0] & ~ProtocolLimits.ListMaskBits) != 0)
        {
            return ProtocolError.BadParameter;
        }

        request = new ReadChangesOfListsRequest(station, frame.Sequence, p[0]);
        return ProtocolError.None;
    }

    /// <summary>
    /// Body == 7 bytes else 04; payload not the characters "STOP" -> 06. Whether the handler has STOP at all (else 05,
    /// as for an unknown command) is the station's, before this.
    /// </summary>
    private static ProtocolError ParseStop(Station station, FreeportFrame frame, ReadOnlySpan<byte> p, out PlcRequest request)
    {
        request = null!;
        if (frame.BodyBytes != FreeportFrame.OverheadBytes + StopPayload.Length)
        {
            return ProtocolError.BadLength;
        }

        if (!p.SequenceEqual(StopPayload))
        {
            return ProtocolError.BadParameter;
        }

        request = new StopRequest(station, frame.Sequence);
        return ProtocolError.None;
    }
}
