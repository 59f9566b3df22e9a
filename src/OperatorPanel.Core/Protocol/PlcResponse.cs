using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Core.Protocol;

/// <summary>A reply from a station to the request with the same <see cref="Sequence"/>.</summary>
public abstract record PlcResponse(Station Station, byte Sequence)
{
    public abstract CommandCode Command { get; }
}

/// <summary>What the handler says about itself and the CPU (docs/protocol.md, "IDENTIFY").</summary>
public sealed record IdentifyResponse(
    Station Station,
    byte Sequence,
    byte ProtocolVersion,
    byte HandlerRevision,
    byte CpuModelCode,
    byte CpuRevisionCode,
    byte WriteMask,
    byte MaxReadData,
    byte ReplyDelayMs,
    byte Smb6,
    byte StatusFlags,
    ushort LastScanMs,
    ushort MinScanMs,
    ushort MaxScanMs) : PlcResponse(Station, Sequence)
{
    public override CommandCode Command => CommandCode.Identify;

    /// <summary>SM0.7: the mode switch is at RUN (off means TERM).</summary>
    public bool ModeSwitchRun => (StatusFlags & 0x01) != 0;
}

/// <summary>The data of every item of the READ request, concatenated in request order.</summary>
public sealed record ReadResponse(Station Station, byte Sequence, ImmutableArray<byte> Data) : PlcResponse(Station, Sequence)
{
    public override CommandCode Command => CommandCode.Read;
}

/// <summary>The written block as read back by the PLC right after the write.</summary>
public sealed record WriteBlockResponse(Station Station, byte Sequence, ImmutableArray<byte> ReadBack) : PlcResponse(Station, Sequence)
{
    public override CommandCode Command => CommandCode.Write;
}

/// <summary>The whole byte holding the bit, read back after the set or reset.</summary>
public sealed record WriteBitResponse(Station Station, byte Sequence, byte ReadBack) : PlcResponse(Station, Sequence)
{
    public override CommandCode Command => CommandCode.WriteBit;
}

/// <summary>A negative reply: the station understood the frame and refused the command.</summary>
public sealed record ErrorResponse(Station Station, byte Sequence, CommandCode RequestCommand, ProtocolError Error) : PlcResponse(Station, Sequence)
{
    public override CommandCode Command => RequestCommand;
}

/// <summary>The list is stored (STATUS 00, no payload).</summary>
public sealed record DefineListResponse(Station Station, byte Sequence) : PlcResponse(Station, Sequence)
{
    public override CommandCode Command => CommandCode.DefineList;
}

/// <summary>The data of every item of the list, concatenated in item order, exactly like a READ reply.</summary>
public sealed record ReadListResponse(Station Station, byte Sequence, ImmutableArray<byte> Data) : PlcResponse(Station, Sequence)
{
    public override CommandCode Command => CommandCode.ReadList;
}
