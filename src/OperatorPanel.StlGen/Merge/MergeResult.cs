using System.Collections.Immutable;

namespace OperatorPanel.StlGen.Merge;

/// <summary>
/// The combined .awl (user's blocks verbatim plus the handler), or, when any error was found, no text and the findings.
/// Warnings come with a written text too.
/// </summary>
public sealed record MergeResult(ImmutableArray<MergeDiagnostic> Diagnostics, string MergedText)
{
    public bool Ok => !Diagnostics.Any(d => d.Severity == MergeSeverity.Error);

    public IEnumerable<MergeDiagnostic> Errors => Diagnostics.Where(d => d.Severity == MergeSeverity.Error);

    public IEnumerable<MergeDiagnostic> Warnings => Diagnostics.Where(d => d.Severity == MergeSeverity.Warning);
}
