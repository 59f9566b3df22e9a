using System.Collections.Immutable;

namespace OperatorPanel.Core.Ppi.S7;

/// <summary>A job PDU as the CPU side reads it (<see cref="S7JobDecoder.TryDecode"/>): what to do, and its reference to echo.</summary>
public abstract record S7Job(ushort Reference)
{
    public sealed record Read(ushort Reference, ImmutableArray<S7Item> Items) : S7Job(Reference);

    /// <summary>Items to write; an item whose data does not fit its address carries the code to answer instead.</summary>
    public sealed record Write(ushort Reference, ImmutableArray<S7WriteItem> Items, ImmutableArray<S7ReturnCode> Problems) : S7Job(Reference);

    public sealed record SetupCommunication(ushort Reference, int PduSize) : S7Job(Reference);

    /// <summary>STOP (16#29) or RUN (16#28 "P_PROGRAM").</summary>
    public sealed record Control(ushort Reference, S7Function Function) : S7Job(Reference);

    /// <summary>A job with another function: answered with a refusal.</summary>
    public sealed record Unsupported(ushort Reference, byte Function) : S7Job(Reference);
}
