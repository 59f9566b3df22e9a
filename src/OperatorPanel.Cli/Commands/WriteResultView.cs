using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Writes;

namespace OperatorPanel.Cli.Commands;

/// <summary>One write as <c>opanel write</c> prints it (text and JSON share this shape).</summary>
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
            WriteOutcome.ReadBackMismatch m => new(address, oldText, newText, "mismatch", item.Show(m.ReadBack.AsSpan()), null, null),
            WriteOutcome.Failed f => new(address, oldText, newText, "failed", null, f.Reason, f.Kind.ToString()),
            _ => throw new ArgumentOutOfRangeException(nameof(outcome), outcome, null),
        };
    }

    /// <summary>0 confirmed; 1 refused before sending or by the PLC (nothing written); 2 link failure or mismatch.</summary>
    [System.Text.Json.Serialization.JsonIgnore]
    public int ExitCode => Outcome switch
    {
        "confirmed" => ExitCodes.Ok,
        "failed" when FailureKind is nameof(WriteFailureKind.InvalidRequest) or nameof(WriteFailureKind.RefusedByPlc) => ExitCodes.BadInput,
        _ => ExitCodes.LinkFailure,
    };

    public void WriteText(TextWriter o)
    {
        var verdict = Outcome switch
        {
            "mismatch" => $"mismatch (read back {ReadBack})",
            "failed" => $"failed: {Reason}",
            _ => Outcome,
        };
        o.WriteLine($"{Address,-8} {Old} -> {New}  {verdict}");
    }
}
