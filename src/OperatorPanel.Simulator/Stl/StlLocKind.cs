namespace OperatorPanel.Simulator.Stl;

internal enum StlLocKind
{
    Constant,
    Direct,
    Local,
    Accumulator,
    Indirect,
}
