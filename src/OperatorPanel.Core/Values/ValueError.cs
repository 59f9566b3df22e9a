using OperatorPanel.Core.Messages;

namespace OperatorPanel.Core.Values;

/// <summary>A refused value: what was wrong, naming the value, the address and what the address takes.</summary>
public sealed record ValueError(ValueErrorKind Kind, string Message)
{
    /// <summary>The message, control characters shown and long words cut: it quotes what was typed or pasted.</summary>
    public string Message { get; init; } = QuotedText.Readable(Message);

    public override string ToString() => Message;
}
