using System.Collections.Immutable;

namespace OperatorPanel.StlGen.Merge;

/// <summary>
/// The combined .awl (user's blocks verbatim plus the handler), or, when any error was found, no text and the findings.
/// Warnings come with a written text too. <see cref="MergedBytes"/> is what is saved: the user's lines in their own
/// bytes; <see cref="MergedText"/> is the same decoded in the user's file's encoding, to show.
/// </summary>
public sealed record MergeResult(ImmutableArray<MergeDiagnostic> Diagnostics, string MergedText)
{
    public byte[] MergedBytes { get; init; } = [];

    public bool Ok => !Diagnostics.Any(d => d.Severity == MergeSeverity.Error);

    public IEnumerable<MergeDiagnostic> Errors => Diagnostics.Where(d => d.Severity == MergeSeverity.Error);

    public IEnumerable<MergeDiagnostic> Warnings => Diagnostics.Where(d => d.Severity == MergeSeverity.Warning);
}
