using System.Collections.Immutable;

namespace OperatorPanel.Core.Protocol;

/// <summary>
/// Requests on the wire (docs/protocol-v2.md, "Commands"): the panel encodes them; a station parses them with
/// <see cref="TryParse"/>. Encoding a request the protocol forbids (21 items, more READ data than
/// <see cref="ProtocolLimits.MaxReadDataFor"/> allows for the item count, 119 write bytes, bit 8, list 5) is a programming
/// error and throws.
/// </summary>
public static partial class RequestCodec
{
    public static byte[] Encode(PlcRequest request) => FrameCodec.Encode(ToFrame(request));

    /// <summary>The frame check of the request as encoded: the REQCHECK every reply to it must carry.</summary>
    public static ushort Check(PlcRequest request) => FrameCodec.CheckOf(ToFrame(request));

    /// <summary>STOP's payload, the characters "STOP": no other command's corrupted frame can carry them by chance.</summary>
    public static ReadOnlySpan<byte> StopPayload => "STOP"u8;

    public static FreeportFrame ToFrame(PlcRequest request)
    {
        ArgumentNullException.ThrowIfNull(request);
        var payload = request switch
        {
            IdentifyRequest => ImmutableArray<byte>.Empty,
            ReadRequest read => ReadPayload(read),
            WriteBlockRequest write => WritePayload(write),
            WriteBitRequest bit => BitPayload(bit),
            DefineListRequest define => [ListId(define.List), .. ReadPayload(new ReadRequest(define.Station, define.Sequence, define.Items))],
            ReadListRequest list => [ListId(list.List)],
            StopRequest => [.. StopPayload],
            ReadChangesRequest changes => [ListId(changes.List), changes.Full ? ReadChangesFlags.Full : (byte)0],
            ReadChangesOfListsRequest lists => [ListMask(lists.ListMask)],
            _ => throw new ArgumentException($"unknown request type {request.GetType().Name}", nameof(request)),
        };
        return new FreeportFrame((byte)request.Station.Address, request.Sequence, (byte)request.Command, payload);
    }

    private static ImmutableArray<byte> ReadPayload(ReadRequest read)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(read.Items.Length, 1, nameof(read));
        ArgumentOutOfRangeException.ThrowIfGreaterThan(read.Items.Length, ProtocolLimits.MaxReadItems, nameof(read));
        ArgumentOutOfRangeException.ThrowIfGreaterThan(read.TotalLength, ProtocolLimits.MaxReadDataFor(read.Items.Length), nameof(read));
        var payload = ImmutableArray.CreateBuilder<byte>(1 + (4 * read.Items.Length));
        payload.Add((byte)read.Items.Length);
        foreach (var item in read.Items)
        {
            ArgumentOutOfRangeException.ThrowIfLessThan(item.Length, 1, nameof(read));
            AddBlock(payload, item.Area, item.Offset);
            payload.Add((byte)item.Length);
        }

        return payload.MoveToImmutable();
    }

    private static byte ListId(int list)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(list, 1);
        ArgumentOutOfRangeException.ThrowIfGreaterThan(list, ProtocolLimits.MaxLists);
        return (byte)list;
    }

    private static byte ListMask(byte mask)
    {
        if (mask == 0 || (mask & ~ProtocolLimits.ListMaskBits) != 0)
        {
            throw new ArgumentOutOfRangeException(nameof(mask), mask, "a list mask names lists 1-4 in bits 0-3, at least one");
        }

        return mask;
    }

    private static ImmutableArray<byte> WritePayload(WriteBlockRequest write)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(write.Data.Length, 1, nameof(write));
        ArgumentOutOfRangeException.ThrowIfGreaterThan(write.Data.Length, ProtocolLimits.MaxWriteData, nameof(write));
        var payload = ImmutableArray.CreateBuilder<byte>(4 + write.Data.Length);
        AddBlock(payload, write.Area, write.Offset);
        payload.Add((byte)write.Data.Length);
        payload.AddRange(write.Data);
        return payload.MoveToImmutable();
    }

    private static ImmutableArray<byte> BitPayload(WriteBitRequest bit)
    {
        ArgumentOutOfRangeException.ThrowIfNegative(bit.Bit, nameof(bit));
        ArgumentOutOfRangeException.ThrowIfGreaterThan(bit.Bit, 7, nameof(bit));
        var payload = ImmutableArray.CreateBuilder<byte>(5);
        AddBlock(payload, bit.Area, bit.Offset);
        payload.Add((byte)bit.Bit);
        payload.Add(bit.Value ? (byte)1 : (byte)0);
        return payload.MoveToImmutable();
    }

    /// <summary>AREA(1) OFFSET(2, big-endian like the S7-200's own words).</summary>
    private static void AddBlock(ImmutableArray<byte>.Builder payload, ProtocolArea area, int offset)
    {
        if (!IsKnownArea((byte)area))
        {
            throw new ArgumentOutOfRangeException(nameof(area), area, "not a protocol area");
        }

        ArgumentOutOfRangeException.ThrowIfNegative(offset);
        ArgumentOutOfRangeException.ThrowIfGreaterThan(offset, ushort.MaxValue);
        payload.Add((byte)area);
        payload.Add((byte)(offset >> 8));
        payload.Add((byte)offset);
    }

    private static bool IsKnownArea(byte code) => code is >= (byte)ProtocolArea.I and <= (byte)ProtocolArea.SM;
}
