namespace OperatorPanel.Core.Stl;

/// <summary>A problem found in .awl text, with its 1-based line: "line 57: ...".</summary>
public sealed record AwlDiagnostic(int Line, string Message)
{
    public override string ToString() => $"line {Line}: {Message}";
}
