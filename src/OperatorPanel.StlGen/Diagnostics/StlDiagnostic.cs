namespace OperatorPanel.StlGen.Diagnostics;

/// <summary>One impossible setting: a stable ID from <see cref="StlDiagnostics"/> and a message naming the bad value and what is allowed.</summary>
public sealed record StlDiagnostic(string Id, string Message)
{
    public override string ToString() => $"{Id}: {Message}";
}
