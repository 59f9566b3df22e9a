using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Writes;

namespace OperatorPanel.Cli.Commands;

/// <summary>One write as <c>opanel write</c> prints it (text and JSON share this shape).</summary>
/// <param name="Address">The address written, e.g. VW200.</param>
/// <param name="Old">The last value read before the write, in the item's notation; "?" when unknown.</param>
/// <param name="New">The value written.</param>
/// <param name="Outcome">confirmed, confirmedByReadBack, mismatch, notApplied, unknown, failed or notSent (interrupted before its turn).</param>
/// <param name="ReadBack">What the PLC holds after a mismatch, or after a lost reply when it could be read.</param>
/// <param name="Reason">Why not confirmed, or why the reply was lost; with the operator's next step.</param>
/// <param name="FailureKind">For "failed": the <see cref="WriteFailureKind"/>.</param>
internal sealed record WriteResultView(string Address, string Old, string New, string Outcome, string? ReadBack, string? Reason, string? FailureKind)
{
    public static WriteResultView From(WriteItem item, PolledValue? old, WriteOutcome outcome)
    {
        var oldText = item.Show(old is { HasValue: true } ? old.Raw.AsSpan() : []);
        var newText = item.Show(item.Request.Value.AsSpan());
        var address = item.Address.ToString();
        return outcome switch
        {
            WriteOutcome.Confirmed => new(address, oldText, newText, "confirmed", null, null, null),
            WriteOutcome.ConfirmedByReadBack c => new(address, oldText, newText, "confirmedByReadBack", item.Show(c.ReadBack.AsSpan()), c.Cause, null),
            WriteOutcome.ReadBackMismatch m => new(address, oldText, newText, "mismatch", item.Show(m.ReadBack.AsSpan()), null, null),
            WriteOutcome.NotApplied n => new(address, oldText, newText, "notApplied", item.Show(n.ReadBack.AsSpan()),
                $"the reply was lost ({n.Cause}) and the PLC still holds {item.Show(n.ReadBack.AsSpan())}; {WriteOutcome.NotApplied.Advice}", null),
            WriteOutcome.Unknown u => new(address, oldText, newText, "unknown", u.ReadBack.IsDefault ? null : item.Show(u.ReadBack.AsSpan()),
                $"{u.Cause}; {u.Detail}; {WriteOutcome.Unknown.Advice}", null),
            WriteOutcome.Failed f => new(address, oldText, newText, "failed", null, f.Reason, f.Kind.ToString()),
            _ => throw new ArgumentOutOfRangeException(nameof(outcome), outcome, null),
        };
    }

    /// <summary>Not sent at all (interrupted before its turn): nothing written.</summary>
    public static WriteResultView NotSent(WriteItem item, PolledValue? old, string reason) =>
        new(item.Address.ToString(), item.Show(old is { HasValue: true } ? old.Raw.AsSpan() : []), item.Show(item.Request.Value.AsSpan()), "notSent", null, reason, null);

    /// <summary>
    /// 0 confirmed (also by read-back after a lost reply); 1 refused before sending or by the PLC (nothing written);
    /// 2 not applied for certain on the link (never sent, or read back unchanged after a lost reply) or read back
    /// differently; 3 unknown whether applied.
    /// </summary>
    [System.Text.Json.Serialization.JsonIgnore]
    public int ExitCode => Outcome switch
    {
        "confirmed" or "confirmedByReadBack" => ExitCodes.Ok,
        "failed" when FailureKind is nameof(WriteFailureKind.InvalidRequest) or nameof(WriteFailureKind.RefusedByPlc) => ExitCodes.BadInput,
        "unknown" => ExitCodes.WriteUnknown,
        "notSent" => ExitCodes.Interrupted,
        _ => ExitCodes.LinkFailure,
    };

    public void WriteText(TextWriter o)
    {
        var verdict = Outcome switch
        {
            "confirmedByReadBack" => $"confirmed (reply lost, read back): {Reason}",
            "mismatch" => $"mismatch (read back {ReadBack})",
            "notApplied" => $"not applied: {Reason}",
            "unknown" => $"unknown: {Reason}",
            "failed" => $"failed: {Reason}",
            "notSent" => $"not sent: {Reason}",
            _ => Outcome,
        };
        o.WriteLine($"{Address,-8} {Old} -> {New}  {verdict}");
    }
}
