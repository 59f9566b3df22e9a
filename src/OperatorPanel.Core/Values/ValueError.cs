namespace OperatorPanel.Core.Values;

/// <summary>A refused value: what was wrong, naming the value, the address and what the address takes.</summary>
public sealed record ValueError(ValueErrorKind Kind, string Message)
{
    public override string ToString() => Message;
}
