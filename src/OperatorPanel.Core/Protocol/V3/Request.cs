using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Core.Protocol.V3;

/// <summary>
/// A v3 request: '&lt;' LEN STATION SEQCMD PAYLOAD CHECK (docs/protocol.md section 1). <see cref="Sequence"/> (0-15)
/// tells a new request from a retry; the reply identifies its request by REQCHECK, the request's B check bytes. The
/// factories below build each command's payload as section 2 defines it.
/// </summary>
public sealed record Request(Station Station, byte Sequence, Command Command, ImmutableArray<byte> Payload)
{
    /// <summary>"STOP": 08 STOP's payload, so no corrupted frame of another command can stop a line.</summary>
    public static readonly ImmutableArray<byte> StopWord = [0x53, 0x54, 0x4F, 0x50];

    /// <summary>The SEQCMD byte: SEQ in the high 4 bits, CMD in the low 4 bits.</summary>
    public byte SequenceAndCommand => (byte)((Sequence << 4) | (byte)Command);

    public bool Equals(Request? other) =>
        other is not null && Station == other.Station && Sequence == other.Sequence && Command == other.Command
        && Payload.AsSpan().SequenceEqual(other.Payload.AsSpan());

    public override int GetHashCode() => HashCode.Combine(Station, Sequence, Command, Payload.Length);

    public static Request Identify(Station station, byte sequence) => new(station, sequence, Command.Identify, []);

    public static Request Read(Station station, byte sequence, ReadItem item) => new(station, sequence, Command.Read, Item(item));

    public static Request Write(Station station, byte sequence, ProtocolArea area, int offset, ReadOnlySpan<byte> data) =>
        new(station, sequence, Command.Write, [.. Item(new ReadItem(area, offset, data.Length)), .. data]);

    /// <summary>The bits of <paramref name="mask"/> in the byte take <paramref name="value"/>'s; the others stay (docs/protocol.md, 04 WRITE BITS).</summary>
    public static Request WriteBits(Station station, byte sequence, ProtocolArea area, int offset, byte mask, byte value) =>
        new(station, sequence, Command.WriteBits, [(byte)area, (byte)(offset >> 8), (byte)offset, mask, value]);

    /// <summary>One bit of a byte: WRITE BITS with a one-bit mask.</summary>
    public static Request WriteBit(Station station, byte sequence, ProtocolArea area, int offset, int bit, bool value) =>
        WriteBits(station, sequence, area, offset, (byte)(1 << bit), value ? (byte)0xFF : (byte)0);

    /// <summary>The station's list, these items in this order (docs/protocol.md, 05 DEFINE LIST).</summary>
    public static Request DefineList(Station station, byte sequence, IEnumerable<ReadItem> items) =>
        new(station, sequence, Command.DefineList, [.. items.SelectMany(i => Item(i))]);

    public static Request ReadList(Station station, byte sequence) => new(station, sequence, Command.ReadList, []);

    public static Request ReadListFull(Station station, byte sequence) => new(station, sequence, Command.ReadListFull, []);

    public static Request Stop(Station station, byte sequence) => new(station, sequence, Command.Stop, StopWord);

    /// <summary>AREA, OFFSET (high byte first), LENGTH: 4 bytes, as READ, WRITE and DEFINE LIST carry an item.</summary>
    private static ImmutableArray<byte> Item(ReadItem item) =>
        [(byte)item.Area, (byte)(item.Offset >> 8), (byte)item.Offset, (byte)item.Length];
}
