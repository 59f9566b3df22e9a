namespace OperatorPanel.Simulator.Stl;

/// <summary>One CALL parameter: the callee's L location, the caller's actual operand, its size, and whether it is copied in and/or out.</summary>
internal sealed record StlParameter(StlLoc Formal, StlLoc Actual, int Bytes, bool In, bool Out);
