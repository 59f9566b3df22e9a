using OperatorPanel.Core.Addressing;
using OperatorPanel.Stl;

namespace OperatorPanel.StlGen.Merge;

/// <summary>
/// One operand of one instruction of the user's program: whether the instruction writes it and how many elements it
/// covers (BMW VW10, VW20, 4 covers four words from each; S V0.0, 12 twelve bits). <see cref="CountUnknown"/> when the
/// count is not a constant, so only the first element is known.
/// </summary>
internal sealed record OperandUse(AwlInstruction Instruction, int Index, AwlOperand Operand, bool Written, long Elements, bool CountUnknown)
{
    public int Line => Instruction.Line;

    /// <summary>First and last byte covered in the operand's area (for a pointer: the byte it points to).</summary>
    public (int First, int Last) Bytes
    {
        get
        {
            var count = Math.Max(1, Elements);
            if (Operand.Kind == AwlOperandKind.Pointer)
            {
                return (Operand.ByteOffset, Operand.ByteOffset);
            }

            if (Operand.Width == AccessWidth.Bit)
            {
                var firstBit = (Operand.ByteOffset * 8L) + (Operand.Bit ?? 0);
                return (Operand.ByteOffset, (int)Math.Min(int.MaxValue, (firstBit + count - 1) / 8));
            }

            var size = Operand.Width switch { AccessWidth.Word => 2L, AccessWidth.DoubleWord => 4L, AccessWidth.Bit or AccessWidth.Byte => 1L };
            return (Operand.ByteOffset, (int)Math.Min(int.MaxValue, Operand.ByteOffset + (size * count) - 1));
        }
    }

    /// <summary>"VW100 (VB100-VB101)" or "VB100".</summary>
    public string Describe(string bytePrefix)
    {
        var (first, last) = Bytes;
        var range = first == last ? $"{bytePrefix}{first}" : $"{bytePrefix}{first}-{bytePrefix}{last}";
        return string.Equals(range, Operand.Text, StringComparison.OrdinalIgnoreCase) ? range : $"{Operand.Text} ({range})";
    }
}
