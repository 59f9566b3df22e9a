using OperatorPanel.Core.Messages;

namespace OperatorPanel.Core.Addressing;

/// <summary>A refused address: what was wrong, in a sentence a technician can act on.</summary>
public sealed record AddressError(AddressErrorKind Kind, string Message)
{
    /// <summary>The message, control characters shown and long words cut: it quotes what was typed or pasted.</summary>
    public string Message { get; init; } = QuotedText.Readable(Message);

    public override string ToString() => Message;
}
