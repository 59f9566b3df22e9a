namespace OperatorPanel.Stl.Instructions;

/// <summary>Why an operand does not fit its position, as a sentence that names the operand.</summary>
public sealed record StlOperandRefusal(StlRefusalKind Kind, string Reason);
