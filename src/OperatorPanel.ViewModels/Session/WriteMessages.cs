using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Values;
using OperatorPanel.Core.Writes;

namespace OperatorPanel.ViewModels.Session;

/// <summary>What the operator reads about a write's outcome, on the row and in the status line.</summary>
internal static class WriteMessages
{
    /// <summary>
    /// Null when confirmed (by the reply or by reading back after a lost reply); else the problem and what to do,
    /// without the address (the row shows that).
    /// </summary>
    public static string? Problem(PlcAddress address, DisplayFormat format, WriteOutcome outcome) => outcome switch
    {
        WriteOutcome.Confirmed or WriteOutcome.ConfirmedByReadBack => null,
        WriteOutcome.ReadBackMismatch m =>
            $"wrote {Text(address, format, m.Expected)}, the PLC read back {Text(address, format, m.ReadBack)}: its program changed it at once",
        WriteOutcome.NotApplied n =>
            $"not applied: the reply was lost ({n.Cause}) and the PLC still holds {Text(address, format, n.ReadBack)}; {WriteOutcome.NotApplied.Advice}",
        WriteOutcome.Unknown u => $"unknown whether written: {u.Cause}; {u.Detail}; {WriteOutcome.Unknown.Advice}",
        WriteOutcome.Failed f => f.Reason,
        _ => throw new ArgumentOutOfRangeException(nameof(outcome), outcome, null),
    };

    /// <summary>
    /// The confirmation before a write: "Set VW10 (Speed) from 1234 to 1500?", the value the panel last read beside the
    /// one to be written ("not read yet", or the last value marked stale, when no good read is at hand).
    /// </summary>
    public static string Question(PlcAddress address, string symbol, string? current, ValueQuality quality, string newValue)
    {
        var now = current is null ? "not read yet"
            : quality == ValueQuality.Good ? current
            : $"{current} (last read, not current)";
        return $"Set {address} ({symbol}) from {now} to {newValue}?";
    }

    public static string StatusText(string symbol, PlcAddress address, DisplayFormat format, string newValue, WriteOutcome outcome) =>
        outcome switch
        {
            WriteOutcome.Confirmed => $"{address} ({symbol}): {newValue} written and confirmed by the PLC",
            WriteOutcome.ConfirmedByReadBack c =>
                $"{address} ({symbol}): {newValue} written, confirmed by reading back (the reply was lost: {c.Cause})",
            WriteOutcome.ReadBackMismatch or WriteOutcome.NotApplied or WriteOutcome.Unknown or WriteOutcome.Failed =>
                $"{address} ({symbol}): write of {newValue} not confirmed: {Problem(address, format, outcome)}",
            _ => throw new ArgumentOutOfRangeException(nameof(outcome), outcome, null),
        };

    private static string Text(PlcAddress address, DisplayFormat format, System.Collections.Immutable.ImmutableArray<byte> raw)
    {
        // A bit's read-back is the whole byte holding it when it came from WRITE BIT; show the bit itself.
        if (address.Width == AccessWidth.Bit)
        {
            return raw.IsDefaultOrEmpty ? "nothing" : (raw[0] != 0 ? "1" : "0");
        }

        return raw.Length == address.Width.ByteCount() ? ValueFormatter.Format(raw.AsSpan(), address.Width, format) : ValueFormatter.Hex(raw.AsSpan());
    }
}
