using OperatorPanel.Core.Messages;

namespace OperatorPanel.Stl;

/// <summary>
/// A problem found in .awl text, with its 1-based line: "line 57: ...". Refusals of <see cref="Checks.AwlProgramCheck"/>
/// carry a stable <see cref="Id"/> (AWL001 ...); parse problems have none.
/// </summary>
public sealed record AwlDiagnostic(int Line, string Message)
{
    /// <summary>The message, control characters shown and long words cut: it quotes the file's text, which may be a megabyte of garbage.</summary>
    public string Message { get; init; } = QuotedText.Readable(Message);

    public string Id { get; init; } = string.Empty;

    public override string ToString() => Id.Length == 0 ? $"line {Line}: {Message}" : $"line {Line}: {Id} {Message}";
}
