using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Core.Protocol;

/// <summary>A reply from a station to the request with the same <see cref="Sequence"/>.</summary>
public abstract record PlcResponse(Station Station, byte Sequence)
{
    public abstract CommandCode Command { get; }

    /// <summary>
    /// REQCHECK: the frame check of the request this reply answers, as the PLC computed and matched it. A decoded
    /// reply always carries the check of the request it was decoded against.
    /// </summary>
    public ushort RequestCheck { get; init; }
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
    ushort MaxScanMs,
    byte Port,
    ushort VFirst,
    ushort VBytes,
    byte Features,
    byte CopyBytes) : PlcResponse(Station, Sequence)
{
    public override CommandCode Command => CommandCode.Identify;

    /// <summary>
    /// The whole protocol v3 IDENTIFY (LIST_ITEMS, LIST_BYTES, MAX_REQUEST, END_TIMEOUT_MS, FEATURES) this response was
    /// mapped from (Link/V3/V3Link.Translate.cs); null for a v2 reply. <see cref="ReplyDelayMs"/> then holds
    /// END_TIMEOUT_MS and <see cref="CopyBytes"/> LIST_BYTES.
    /// </summary>
    public V3.Identity? V3Identity { get; init; }

    /// <summary>SM0.7: the mode switch is at RUN (off means TERM).</summary>
    public bool ModeSwitchRun => (StatusFlags & 0x01) != 0;

    /// <summary>FEATURES bit 0: the handler answers STOP (07).</summary>
    public bool StopEnabled => (Features & HandlerIdentity.StopFeature) != 0;

    /// <summary>FEATURES bit 1: READ CHANGES can answer with pairs (the handler keeps copies).</summary>
    public bool HasCopies => (Features & HandlerIdentity.CopiesFeature) != 0;

    /// <summary>FEATURES bit 2: the handler answers 09 READ CHANGES OF LISTS.</summary>
    public bool HasChangesOfLists => (Features & HandlerIdentity.ChangesOfListsFeature) != 0;
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

/// <summary>The station accepted STOP; it goes to STOP once this reply is sent, and speaks PPI afterwards.</summary>
public sealed record StopResponse(Station Station, byte Sequence) : PlcResponse(Station, Sequence)
{
    public override CommandCode Command => CommandCode.Stop;
}

/// <summary>
/// A READ CHANGES reply: with <see cref="Full"/> the list's whole data in <see cref="Data"/> (K = 16#FF); otherwise the
/// bytes that differ from the handler's copy in <see cref="Changes"/>, ascending by index (K pairs, 0-127). Either
/// way the handler's copy now holds the values this reply reports.
/// </summary>
public sealed record ReadChangesResponse(Station Station, byte Sequence, bool Full, ImmutableArray<byte> Data, ImmutableArray<ChangedByte> Changes)
    : PlcResponse(Station, Sequence)
{
    public override CommandCode Command => CommandCode.ReadChanges;

    /// <summary>A FULL reply: the whole list's data.</summary>
    public static ReadChangesResponse Whole(Station station, byte sequence, ImmutableArray<byte> data) => new(station, sequence, true, data, []);

    /// <summary>A pairs reply: the changed bytes (none for an idle list).</summary>
    public static ReadChangesResponse Pairs(Station station, byte sequence, ImmutableArray<ChangedByte> changes) => new(station, sequence, false, [], changes);

    /// <summary>
    /// The list's data now: <see cref="Data"/> for a FULL reply, else <paramref name="previous"/> (what the PC holds
    /// from its last good reply of this list) with the changes applied. False when a change's index lies outside it.
    /// </summary>
    public bool TryApply(ReadOnlySpan<byte> previous, out ImmutableArray<byte> current)
    {
        if (Full)
        {
            current = Data;
            return true;
        }

        return ChangedByte.TryApply(previous, Changes, out current);
    }

    public bool Equals(ReadChangesResponse? other) =>
        other is not null && Station == other.Station && Sequence == other.Sequence && RequestCheck == other.RequestCheck
        && Full == other.Full && Data.AsSpan().SequenceEqual(other.Data.AsSpan()) && Changes.AsSpan().SequenceEqual(other.Changes.AsSpan());

    public override int GetHashCode() => HashCode.Combine(Station, Sequence, Full, Data.Length, Changes.Length);
}

/// <summary>
/// A READ CHANGES OF LISTS reply: one entry per list of the request's mask, in ascending list id. Each entry's list
/// copy in the handler now holds the values the PC has after applying it, except for a REREAD entry, whose copy is
/// invalid.
/// </summary>
public sealed record ReadChangesOfListsResponse(Station Station, byte Sequence, ImmutableArray<ListChanges> Lists)
    : PlcResponse(Station, Sequence)
{
    public override CommandCode Command => CommandCode.ReadChangesOfLists;

    public bool Equals(ReadChangesOfListsResponse? other) =>
        other is not null && Station == other.Station && Sequence == other.Sequence && RequestCheck == other.RequestCheck
        && Lists.SequenceEqual(other.Lists);

    public override int GetHashCode() => HashCode.Combine(Station, Sequence, Lists.Length);
}
