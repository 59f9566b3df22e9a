using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Core.Protocol;

/// <summary>The station side of DEFINE LIST and READ LIST (docs/protocol.md, "Processing order", step 6).</summary>
public static partial class RequestCodec
{
    /// <summary>
    /// Body &gt;= 6 bytes and COUNT 1-20 else 04; body == 6 + 4 x COUNT else 04; LIST not 1-4 -> 06; then the items
    /// exactly like a READ. The tail capacity check is the station's (it needs the stored lists).
    /// </summary>
    private static ProtocolError ParseDefineList(Station station, FreeportFrame frame, ReadOnlySpan<byte> p, IRequestTarget? target, out PlcRequest request)
    {
        request = null!;
        if (frame.BodyBytes < 6 || p[1] is < 1 or > ProtocolLimits.MaxReadItems || frame.BodyBytes != 6 + (4 * p[1]))
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
    /// Body == 5 bytes else 04. Any LIST byte parses: one outside 1-4 is simply never defined, so the station answers 07.
    /// </summary>
    private static ProtocolError ParseReadList(Station station, FreeportFrame frame, ReadOnlySpan<byte> p, out PlcRequest request)
    {
        request = null!;
        if (frame.BodyBytes != 5)
        {
            return ProtocolError.BadLength;
        }

        request = new ReadListRequest(station, frame.Sequence, p[0]);
        return ProtocolError.None;
    }
}
