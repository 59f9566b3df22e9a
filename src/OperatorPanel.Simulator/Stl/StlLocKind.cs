namespace OperatorPanel.Simulator.Stl;

internal enum StlLocKind
{
    Constant,
    Direct,
    Local,
    Accumulator,
    Indirect,

    /// <summary>Timer Tn (n in Offset): its bit as a bit operand, its current value as a word.</summary>
    Timer,

    /// <summary>Counter Cn (n in Offset): its bit as a bit operand, its current value as a word.</summary>
    Counter,
}
