using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Core.Protocol;

/// <summary>
/// A request from the panel to one station. <see cref="Sequence"/> is echoed by the reply; the link that sends the request
/// stamps it (Link/PlcLink), so callers build requests without one (the constructors without it leave 0).
/// </summary>
public abstract record PlcRequest(Station Station, byte Sequence)
{
    public abstract CommandCode Command { get; }
}

/// <summary>Ask for protocol version, handler configuration, SMB6, mode switch and scan times.</summary>
public sealed record IdentifyRequest(Station Station, byte Sequence) : PlcRequest(Station, Sequence)
{
    public IdentifyRequest(Station station)
        : this(station, 0)
    {
    }

    public override CommandCode Command => CommandCode.Identify;
}

/// <summary>
/// Read up to <see cref="ProtocolLimits.MaxReadItems"/> blocks in one exchange, at most
/// <see cref="ProtocolLimits.MaxReadDataFor"/>(item count) bytes in all.
/// </summary>
public sealed record ReadRequest(Station Station, byte Sequence, ImmutableArray<ReadItem> Items) : PlcRequest(Station, Sequence)
{
    public ReadRequest(Station station, ImmutableArray<ReadItem> items)
        : this(station, 0, items)
    {
    }

    public override CommandCode Command => CommandCode.Read;

    public int TotalLength => Items.Sum(i => i.Length);
}

/// <summary>Write a block of bytes; the reply carries the same bytes read back after the write.</summary>
public sealed record WriteBlockRequest(Station Station, byte Sequence, ProtocolArea Area, int Offset, ImmutableArray<byte> Data)
    : PlcRequest(Station, Sequence)
{
    public WriteBlockRequest(Station station, ProtocolArea area, int offset, ImmutableArray<byte> data)
        : this(station, 0, area, offset, data)
    {
    }

    public override CommandCode Command => CommandCode.Write;
}

/// <summary>Set or reset one bit on the PLC itself, so a bit the PLC program changed meanwhile is never clobbered.</summary>
public sealed record WriteBitRequest(Station Station, byte Sequence, ProtocolArea Area, int Offset, int Bit, bool Value)
    : PlcRequest(Station, Sequence)
{
    public WriteBitRequest(Station station, ProtocolArea area, int offset, int bit, bool value)
        : this(station, 0, area, offset, bit, value)
    {
    }

    public override CommandCode Command => CommandCode.WriteBit;
}

/// <summary>
/// Store <see cref="Items"/> in the handler under <see cref="List"/> (1-4), so <see cref="ReadListRequest"/> can read
/// them with a 12-character request. Checked like a READ, plus the tail capacity rule (docs/protocol-v2.md, "Lists").
/// </summary>
public sealed record DefineListRequest(Station Station, byte Sequence, int List, ImmutableArray<ReadItem> Items) : PlcRequest(Station, Sequence)
{
    public DefineListRequest(Station station, int list, ImmutableArray<ReadItem> items)
        : this(station, 0, list, items)
    {
    }

    public override CommandCode Command => CommandCode.DefineList;

    public int TotalLength => Items.Sum(i => i.Length);
}

/// <summary>Read the items stored under <see cref="List"/>; the reply is that of a READ of them.</summary>
public sealed record ReadListRequest(Station Station, byte Sequence, int List) : PlcRequest(Station, Sequence)
{
    public ReadListRequest(Station station, int list)
        : this(station, 0, list)
    {
    }

    public override CommandCode Command => CommandCode.ReadList;
}

/// <summary>
/// Put the CPU into STOP: the payload is the four characters "STOP" so that no corrupted frame of another command can
/// stop a line. A handler generated without STOP answers error 05; after the reply the port speaks PPI.
/// </summary>
public sealed record StopRequest(Station Station, byte Sequence) : PlcRequest(Station, Sequence)
{
    public StopRequest(Station station)
        : this(station, 0)
    {
    }

    public override CommandCode Command => CommandCode.Stop;
}

/// <summary>
/// Read list <see cref="List"/> as the bytes changed since the handler's copy, or whole when <see cref="Full"/>.
/// PC rule (docs/protocol-v2.md): after any READ CHANGES that did not bring a good reply, the next one of that list must
/// be <see cref="Full"/>, because the copy moved on with the reply that was lost.
/// </summary>
public sealed record ReadChangesRequest(Station Station, byte Sequence, int List, bool Full) : PlcRequest(Station, Sequence)
{
    public ReadChangesRequest(Station station, int list, bool full)
        : this(station, 0, list, full)
    {
    }

    public override CommandCode Command => CommandCode.ReadChanges;
}

/// <summary>
/// Read the changes of the lists in <see cref="ListMask"/> (bit n-1 = list n) in one exchange. PC rule
/// (docs/protocol-v2.md): a list may be in the mask only when an 08 READ CHANGES of it without FULL would be allowed, and
/// after a 09 that did not bring a good reply every list of its mask is next read with 08 FULL.
/// </summary>
public sealed record ReadChangesOfListsRequest(Station Station, byte Sequence, byte ListMask) : PlcRequest(Station, Sequence)
{
    public ReadChangesOfListsRequest(Station station, byte listMask)
        : this(station, 0, listMask)
    {
    }

    public override CommandCode Command => CommandCode.ReadChangesOfLists;

    /// <summary>The list ids in the mask, ascending: the order of the reply's entries.</summary>
    public IReadOnlyList<int> Lists => [.. Enumerable.Range(1, ProtocolLimits.MaxLists).Where(list => (ListMask & MaskBit(list)) != 0)];

    /// <summary>The mask bit of list <paramref name="list"/> (1-4).</summary>
    public static byte MaskBit(int list) => (byte)(1 << (list - 1));

    /// <summary>The mask naming <paramref name="lists"/>.</summary>
    public static byte MaskOf(IEnumerable<int> lists) => (byte)lists.Aggregate(0, (mask, list) => mask | MaskBit(list));
}
