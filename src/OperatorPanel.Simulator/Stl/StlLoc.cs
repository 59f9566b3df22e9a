namespace OperatorPanel.Simulator.Stl;

/// <summary>
/// An operand resolved at load time: a constant, a byte offset in an area (area = (int)MemoryArea), an offset in the
/// current block's L memory, an accumulator, or a pointer held by another location. No text is looked at while running.
/// </summary>
internal sealed class StlLoc
{
    public required StlLocKind Kind { get; init; }

    /// <summary>(int)MemoryArea of a direct address.</summary>
    public int Area { get; init; }

    /// <summary>Byte offset (direct, local) or accumulator number.</summary>
    public int Offset { get; init; }

    /// <summary>Bit 0-7 for bit operands.</summary>
    public int Bit { get; init; }

    /// <summary>Raw bits of a constant (a pointer constant is its encoded address).</summary>
    public uint Value { get; init; }

    /// <summary>For an indirect operand: the double word that holds the pointer.</summary>
    public StlLoc? Holder { get; init; }
}
