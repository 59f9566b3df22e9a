namespace OperatorPanel.Stl.Instructions;

/// <summary>
/// One operand of an instruction as the manual's table gives it: its name (IN, OUT, N), data type, allowed kinds,
/// what the instruction does with it, the range of a constant, and how many elements a count widens it to.
/// </summary>
public sealed record StlOperandSpec(string Name, StlDataType Type, StlOperandKinds Kinds, StlAccess Access)
{
    /// <summary>Smallest constant the manual allows here (N of S/R is 1-255; a label 0-255); null: the data type's range.</summary>
    public long? Min { get; init; }

    /// <summary>Largest constant allowed here; null: the data type's range.</summary>
    public long? Max { get; init; }

    /// <summary>How many elements the instruction's count operand makes of this one.</summary>
    public StlExtent Extent { get; init; } = StlExtent.One;

    /// <summary>Elements a fixed-size operand covers: 8 bytes of a TODR clock buffer, 256 of an XMT/RCV buffer.</summary>
    public int Length { get; init; } = 1;

    public bool IsWritten => Access != StlAccess.Read;

    /// <summary>Bytes of one element: 0 for a bit, 1, 2 or 4; -1 for a number of something (label, POU, event, port, T, C).</summary>
    public int Bytes => Type switch
    {
        StlDataType.Bool => 0,
        StlDataType.Byte or StlDataType.String => 1,
        StlDataType.Word or StlDataType.Int => 2,
        StlDataType.DWord or StlDataType.DInt or StlDataType.Real => 4,
        StlDataType.Label or StlDataType.Subroutine or StlDataType.InterruptRoutine or StlDataType.Event
            or StlDataType.Port or StlDataType.Timer or StlDataType.Counter => -1,
    };

    public StlOperandSpec Range(long min, long max) => this with { Min = min, Max = max };

    public StlOperandSpec Widened(StlExtent extent) => this with { Extent = extent };

    public StlOperandSpec Covering(int elements) => this with { Length = elements };
}
