using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Values;
using OperatorPanel.Core.Writes;

namespace OperatorPanel.ViewModels.Session;

/// <summary>What the operator reads about a write's outcome, on the row and in the status line.</summary>
internal static class WriteMessages
{
    /// <summary>Null when confirmed; else the problem, without the address (the row shows that).</summary>
    public static string? Problem(PlcAddress address, DisplayFormat format, WriteOutcome outcome) => outcome switch
    {
        WriteOutcome.Confirmed => null,
        WriteOutcome.ReadBackMismatch m =>
            $"wrote {Text(address, format, m.Expected)}, the PLC read back {Text(address, format, m.ReadBack)}: its program changed it at once",
        WriteOutcome.Failed f => f.Reason,
        _ => throw new ArgumentOutOfRangeException(nameof(outcome), outcome, null),
    };

    public static string StatusText(string symbol, PlcAddress address, DisplayFormat format, string newValue, WriteOutcome outcome) =>
        Problem(address, format, outcome) is { } problem
            ? $"{address} ({symbol}): write of {newValue} not confirmed: {problem}"
            : $"{address} ({symbol}): {newValue} written and confirmed by the PLC";

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
