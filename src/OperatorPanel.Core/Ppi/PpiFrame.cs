using System.Collections.Immutable;

namespace OperatorPanel.Core.Ppi;

/// <summary>
/// One FDL telegram on a PPI bus (docs/ppi.md section 2). <see cref="Destination"/> and <see cref="Source"/> are PPI
/// station addresses 0-126 (the PC defaults to 0, a CPU to 2); <see cref="FunctionCode"/> and <see cref="Data"/> are
/// empty for the formats that have none (<see cref="PpiFrameKind.ShortAcknowledge"/> has neither address).
/// </summary>
public sealed record PpiFrame(PpiFrameKind Kind, byte Destination, byte Source, byte FunctionCode, ImmutableArray<byte> Data)
{
    /// <summary>Highest station address on a PPI network (0-126; ML1409368 p. 159).</summary>
    public const int MaxAddress = 126;

    public static PpiFrame ShortAcknowledge { get; } = new(PpiFrameKind.ShortAcknowledge, 0, 0, 0, []);

    public static PpiFrame Variable(byte destination, byte source, byte functionCode, ReadOnlySpan<byte> data)
    {
        ArgumentOutOfRangeException.ThrowIfZero(data.Length, nameof(data));
        ArgumentOutOfRangeException.ThrowIfGreaterThan(data.Length, PpiFrameCodec.MaxData, nameof(data));
        return new(PpiFrameKind.Variable, destination, source, functionCode, [.. data]);
    }

    public static PpiFrame Fixed(byte destination, byte source, byte functionCode) =>
        new(PpiFrameKind.Fixed, destination, source, functionCode, []);

    public static PpiFrame Token(byte destination, byte source) => new(PpiFrameKind.Token, destination, source, 0, []);

    /// <summary>Equality by value, data included (records compare ImmutableArray by reference).</summary>
    public bool Equals(PpiFrame? other) =>
        other is not null && Kind == other.Kind && Destination == other.Destination && Source == other.Source
        && FunctionCode == other.FunctionCode && Data.AsSpan().SequenceEqual(other.Data.AsSpan());

    public override int GetHashCode() => HashCode.Combine(Kind, Destination, Source, FunctionCode, Data.Length);

    public override string ToString() => Kind switch
    {
        PpiFrameKind.ShortAcknowledge => "SC E5",
        PpiFrameKind.Token => $"SD4 {Source}->{Destination}",
        PpiFrameKind.Fixed => $"SD1 {Source}->{Destination} FC {FunctionCode:X2}",
        _ => $"SD2 {Source}->{Destination} FC {FunctionCode:X2} {Data.Length} bytes",
    };
}
