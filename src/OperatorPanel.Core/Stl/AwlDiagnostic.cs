using System.Text.RegularExpressions;

namespace OperatorPanel.Core.Stl;

/// <summary>
/// A problem found in .awl text, with its 1-based line: "line 57: ...". Refusals of <see cref="Checks.AwlProgramCheck"/>
/// carry a stable <see cref="Id"/> (AWL001 ...); parse problems have none.
/// </summary>
public sealed partial record AwlDiagnostic(int Line, string Message)
{
    /// <summary>Longer runs of text without a space are cut: a diagnostic quotes the file's text, which may be a megabyte of garbage.</summary>
    private const int MaxWordChars = 40;

    public string Message { get; init; } = LongWord().Replace(Message, m => m.Value[..MaxWordChars] + "...");

    public string Id { get; init; } = string.Empty;

    public override string ToString() => Id.Length == 0 ? $"line {Line}: {Message}" : $"line {Line}: {Id} {Message}";

    [GeneratedRegex(@"\S{41,}")]
    private static partial Regex LongWord();
}
