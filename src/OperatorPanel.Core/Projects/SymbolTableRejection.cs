namespace OperatorPanel.Core.Projects;

/// <summary>A pasted symbol table line that was not imported, with its 1-based line number and why.</summary>
public sealed record SymbolTableRejection(int LineNumber, string Line, string Reason)
{
    public override string ToString() => $"line {LineNumber}: {Reason}";
}
