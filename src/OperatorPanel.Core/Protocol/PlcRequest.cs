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
/// them with a 12-character request. Checked like a READ, plus the tail capacity rule (docs/protocol.md, "Lists").
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
/// PC rule (docs/protocol.md): after any READ CHANGES that did not bring a good reply, the next one of that list must
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
