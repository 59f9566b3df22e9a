namespace OperatorPanel.StlGen.Merge;

/// <summary>
/// One merge finding: a stable ID from <see cref="Diagnostics.StlDiagnostics"/>, the 1-based line in the user's file
/// (0 when it concerns no line, e.g. an impossible handler setting) and a message that says what to do.
/// </summary>
public sealed record MergeDiagnostic(string Id, MergeSeverity Severity, int Line, string Message)
{
    /// <summary>"57: STL022 VW100 ..." ; the CLI puts the file name in front.</summary>
    public override string ToString() => Line > 0 ? $"{Line}: {Id} {Message}" : $"{Id} {Message}";
}
