using System.Collections.Immutable;

namespace OperatorPanel.Core.Writes;

/// <summary>
/// What became of a <see cref="WriteRequest"/>: every write ends in exactly one of these, never silently. Values are
/// in the representation of <see cref="WriteRequest.Value"/> (bytes, or 00/01 for a bit). A write whose reply was lost
/// (timeout, garbled reply, or a reply to a corrupted copy of the request) is never repeated: the panel reads the
/// target back and reports <see cref="ConfirmedByReadBack"/>, <see cref="NotApplied"/> or <see cref="Unknown"/>.
/// </summary>
public abstract record WriteOutcome
{
    private WriteOutcome()
    {
    }

    /// <summary>The PLC answered exactly the request sent and read back exactly what was written.</summary>
    public sealed record Confirmed(ImmutableArray<byte> ReadBack) : WriteOutcome;

    /// <summary>The write was executed but the PLC read back something else (its program overwrote the value at once).</summary>
    public sealed record ReadBackMismatch(ImmutableArray<byte> Expected, ImmutableArray<byte> ReadBack) : WriteOutcome;

    /// <summary>
    /// Not written, for certain: refused before sending, refused by the PLC, or never sent (see <see cref="WriteFailureKind"/>).
    /// </summary>
    public sealed record Failed(string Reason, WriteFailureKind Kind) : WriteOutcome;

    /// <summary>The reply was lost (<paramref name="Cause"/>); a read-back shows the PLC holds the new value.</summary>
    public sealed record ConfirmedByReadBack(ImmutableArray<byte> ReadBack, string Cause) : WriteOutcome
    {
        public const string Advice = "nothing to do";
    }

    /// <summary>
    /// The reply was lost (<paramref name="Cause"/>); a read-back shows the PLC still holds the old value: the request
    /// was lost on the way, or the PLC program put the old value back at once.
    /// </summary>
    public sealed record NotApplied(ImmutableArray<byte> ReadBack, string Cause) : WriteOutcome
    {
        public const string Advice = "write it again if it is still wanted";
    }

    /// <summary>
    /// The reply was lost (<paramref name="Cause"/>) and the read-back could not settle it: <paramref name="ReadBack"/>
    /// is neither the old nor the new value, or default when the read-back failed too (<paramref name="Detail"/> says which).
    /// </summary>
    public sealed record Unknown(ImmutableArray<byte> ReadBack, string Cause, string Detail) : WriteOutcome
    {
        public const string Advice = "the PLC may or may not have applied it: check the value on the PLC before writing again";
    }
}
