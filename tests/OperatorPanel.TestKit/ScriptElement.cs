namespace OperatorPanel.TestKit;

/// <summary>One token of a <see cref="ScriptedTransport"/> line.</summary>
internal abstract record ScriptElement
{
    /// <summary>An exact byte: hex pair or a character of a "quoted" string.</summary>
    internal sealed record Literal(byte Value) : ScriptElement;

    /// <summary>"??": any one byte (requests only).</summary>
    internal sealed record AnyByte : ScriptElement;

    /// <summary>"{name}": in a request, captures two bytes (a hex byte as sent, e.g. SEQ); in a response, echoes them.</summary>
    internal sealed record Capture(string Name) : ScriptElement;

    /// <summary>"{bcc}" (responses only): XOR of the characters after the line's last '&lt;', as two uppercase hex digits.</summary>
    internal sealed record Bcc : ScriptElement;
}
