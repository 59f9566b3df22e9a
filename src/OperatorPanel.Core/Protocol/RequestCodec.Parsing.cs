using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Core.Protocol;

/// <summary>The station side: processing order steps 5 and 6 (docs/protocol-v2.md, "Processing order").</summary>
public static partial class RequestCodec
{
    /// <summary>
    /// Parses a frame that passed step 2 (<see cref="FrameCodec.TryDecode"/>). Returns false with
    /// <see cref="ProtocolError.None"/> when the frame gets no reply at all (station byte outside 1-126, or a reply
    /// overheard on the bus, step 4), and false with an error code when the station must answer with that code.
    /// Without a <paramref name="target"/> the area-size and writability checks are skipped.
    /// Step 3 (is it my station?) is the caller's.
    /// </summary>
    public static bool TryParse(FreeportFrame frame, IRequestTarget? target, out PlcRequest request, out ProtocolError error)
    {
        ArgumentNullException.ThrowIfNull(frame);
        request = null!;
        if (frame.Station is < Station.Min or > Station.Max || frame.IsReply)
        {
            error = ProtocolError.None;
            return false;
        }

        var station = new Station(frame.Station);
        var p = frame.Payload.AsSpan();
        var command = (CommandCode)frame.Command;

        // A code off the wire that names no command is error 05; the named ones are switched over by name, so a new
        // command fails the build here until it is parsed.
        error = !Enum.IsDefined(command) ? ProtocolError.UnknownCommand : command switch
        {
            CommandCode.Identify => ParseIdentify(station, frame, out request),
            CommandCode.Read => ParseRead(station, frame, p, target, out request),
            CommandCode.Write => ParseWrite(station, frame, p, target, out request),
            CommandCode.WriteBit => ParseWriteBit(station, frame, p, target, out request),
            CommandCode.DefineList => ParseDefineList(station, frame, p, target, out request),
            CommandCode.ReadList => ParseReadList(station, frame, p, out request),
            CommandCode.Stop => ParseStop(station, frame, p, out request),
            CommandCode.ReadChanges => ParseReadChanges(station, frame, p, out request),
            CommandCode.ReadChangesOfLists => ParseReadChangesOfLists(station, frame, p, out request),
        };
        if (error != ProtocolError.None)
        {
            request = null!;
            return false;
        }

        return true;
    }

    private static ProtocolError ParseIdentify(Station station, FreeportFrame frame, out PlcRequest request)
    {
        request = new IdentifyRequest(station, frame.Sequence);
        return frame.BodyBytes == 3 ? ProtocolError.None : ProtocolError.BadLength;
    }

    private static ProtocolError ParseRead(Station station, FreeportFrame frame, ReadOnlySpan<byte> p, IRequestTarget? target, out PlcRequest request)
    {
        request = null!;
        if (frame.BodyBytes < 4 || p[0] is < 1 or > ProtocolLimits.MaxReadItems || frame.BodyBytes != 4 + (4 * p[0]))
        {
            return ProtocolError.BadLength;
        }

        var error = ParseItems(p[1..], p[0], target, out var items);
        if (error == ProtocolError.None)
        {
            request = new ReadRequest(station, frame.Sequence, items);
        }

        return error;
    }

    /// <summary>
    /// COUNT items in order: LENGTH 0 -> 04, unknown area or past its end -> 02 (first failing item decides); then the
    /// last check of step 6, 2D + 4N &lt;= 237 (the reply must end before the descriptors at the buffer's end) -> 04.
    /// </summary>
    private static ProtocolError ParseItems(ReadOnlySpan<byte> p, int count, IRequestTarget? target, out ImmutableArray<ReadItem> items)
    {
        items = default;
        var builder = ImmutableArray.CreateBuilder<ReadItem>(count);
        for (var i = 0; i < count; i++)
        {
            var at = 4 * i;
            var item = new ReadItem((ProtocolArea)p[at], (p[at + 1] << 8) | p[at + 2], p[at + 3]);
            if (item.Length == 0)
            {
                return ProtocolError.BadLength;
            }

            if (!IsKnownArea(p[at]) || (target is not null && item.Offset + item.Length > target.AreaBytes(item.Area)))
            {
                return ProtocolError.AddressOutOfRange;
            }

            builder.Add(item);
        }

        items = builder.MoveToImmutable();
        return items.Sum(i => i.Length) > ProtocolLimits.MaxReadDataFor(count) ? ProtocolError.BadLength : ProtocolError.None;
    }

    private static ProtocolError ParseWrite(Station station, FreeportFrame frame, ReadOnlySpan<byte> p, IRequestTarget? target, out PlcRequest request)
    {
        request = null!;
        if (frame.BodyBytes < 7 || p[3] is < 1 or > ProtocolLimits.MaxWriteData || frame.BodyBytes != 7 + p[3])
        {
            return ProtocolError.BadLength;
        }

        var area = (ProtocolArea)p[0];
        var offset = (p[1] << 8) | p[2];
        var check = CheckBlock(p[0], offset, p[3], target);
        request = new WriteBlockRequest(station, frame.Sequence, area, offset, [.. p[4..]]);
        return check;
    }

    private static ProtocolError ParseWriteBit(Station station, FreeportFrame frame, ReadOnlySpan<byte> p, IRequestTarget? target, out PlcRequest request)
    {
        request = null!;
        if (frame.BodyBytes != 8)
        {
            return ProtocolError.BadLength;
        }

        var offset = (p[1] << 8) | p[2];
        var check = CheckBlock(p[0], offset, 1, target);
        if (check != ProtocolError.None)
        {
            return check;
        }

        if (p[3] > 7 || p[4] > 1)
        {
            return ProtocolError.BadParameter;
        }

        request = new WriteBitRequest(station, frame.Sequence, (ProtocolArea)p[0], offset, p[3], p[4] == 1);
        return ProtocolError.None;
    }

    /// <summary>Unknown area or past its end -> 02, then protected -> 03 (step 6, WRITE and WRITE BIT).</summary>
    private static ProtocolError CheckBlock(byte areaCode, int offset, int length, IRequestTarget? target)
    {
        if (!IsKnownArea(areaCode))
        {
            return ProtocolError.AddressOutOfRange;
        }

        var area = (ProtocolArea)areaCode;
        if (target is null)
        {
            return ProtocolError.None;
        }

        if (offset + length > target.AreaBytes(area))
        {
            return ProtocolError.AddressOutOfRange;
        }

        return target.IsWritable(area, offset, length) ? ProtocolError.None : ProtocolError.NotWritable;
    }
}
