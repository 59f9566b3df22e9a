namespace OperatorPanel.Stl;

/// <summary>What an STL operand text denotes.</summary>
public enum AwlOperandKind
{
    /// <summary>A memory address of any area: I0.0, VB100, SMW22, LD4, AC1, T37, C5, HC0, AIW0.</summary>
    Address,

    /// <summary>A number (100, -5, 16#3C, 2#1010, 1.5) or a string ('AB').</summary>
    Constant,

    /// <summary>The address of a byte (or T/C): &amp;VB100.</summary>
    Pointer,

    /// <summary>The memory a pointer in VD, LD or AC1-AC3 points to: *VD10, *LD4, *AC1.</summary>
    Indirect,

    /// <summary>A local variable of the block: #count.</summary>
    Local,

    /// <summary>A bare name: a block (OP_RX, SBR_0, INT_1) or a symbol.</summary>
    Symbol,
}
