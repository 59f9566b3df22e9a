using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Stl;

/// <summary>
/// One classified STL operand. For <see cref="AwlOperandKind.Address"/> the area, width, byte offset and bit say where
/// (for AC, T, C and HC the offset is the number: AC1 has offset 1); for a <see cref="AwlOperandKind.Pointer"/> they
/// describe the target (&amp;VB100), for an <see cref="AwlOperandKind.Indirect"/> the double word holding the pointer
/// (*VD10 = V, 10; *AC1 = AC, 1). Read with <see cref="TryParse"/>.
/// </summary>
public sealed partial record AwlOperand
{
    public required AwlOperandKind Kind { get; init; }

    /// <summary>The operand as written, trimmed.</summary>
    public required string Text { get; init; }

    public MemoryArea Area { get; init; }

    public AccessWidth Width { get; init; }

    public int ByteOffset { get; init; }

    /// <summary>Bit 0-7 of a bit address; null otherwise.</summary>
    public int? Bit { get; init; }

    public AwlConstantKind ConstantKind { get; init; }

    /// <summary>Value of an integer constant.</summary>
    public long Integer { get; init; }

    /// <summary>Value of a real constant.</summary>
    public double Real { get; init; }

    /// <summary>Name of a local (without #) or of a symbol; characters of a string constant.</summary>
    public string Name { get; init; } = string.Empty;

    /// <summary>The symbol written before the address in the NAME:ADDRESS form (<c>P13a_Rot_Des</c> of <c>P13a_Rot_Des:M2.0</c>); null otherwise.</summary>
    public string? SymbolName { get; init; }

    public override string ToString() => Text;
}
