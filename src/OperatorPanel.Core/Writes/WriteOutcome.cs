using System.Collections.Immutable;

namespace OperatorPanel.Core.Writes;

/// <summary>
/// What became of a <see cref="WriteRequest"/>: every write ends in exactly one of these, never silently. Values are
/// in the representation of <see cref="WriteRequest.Value"/> (bytes, or 00/01 for a bit).
/// </summary>
public abstract record WriteOutcome
{
    private WriteOutcome()
    {
    }

    /// <summary>The PLC read back exactly what was written.</summary>
    public sealed record Confirmed(ImmutableArray<byte> ReadBack) : WriteOutcome;

    /// <summary>The write was executed but the PLC read back something else (its program overwrote the value at once).</summary>
    public sealed record ReadBackMismatch(ImmutableArray<byte> Expected, ImmutableArray<byte> ReadBack) : WriteOutcome;

    public sealed record Failed(string Reason, WriteFailureKind Kind) : WriteOutcome;
}
