using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using Serilog;

namespace OperatorPanel.Core.Writes;

/// <summary>
/// Every write to a PLC is logged with station, address, old value (last polled, or "unknown") and new value, and its
/// outcome: Information when confirmed (by the reply or, after a lost reply, by
/// reading back), Warning otherwise. Values print as the manual writes constants: 16#002A, or 0/1 for a bit.
/// </summary>
internal static class WriteLog
{
    public const string Unknown = "unknown";

    public static void Record(ILogger logger, WriteRequest request, string oldValue, WriteOutcome outcome)
    {
        var station = request.Station.Address;
        var address = request.Address.ToString();
        var newValue = Format(request.Address, request.Value);
        switch (outcome)
        {
            case WriteOutcome.Confirmed:
                logger.Information(
                    "Write station {Station} {Address:l}: {OldValue:l} -> {NewValue:l} confirmed", station, address, oldValue, newValue);
                break;
            case WriteOutcome.ReadBackMismatch mismatch:
                logger.Warning(
                    "Write station {Station} {Address:l}: {OldValue:l} -> {NewValue:l} read back {ReadBack:l}",
                    station, address, oldValue, newValue, Format(request.Address, mismatch.ReadBack));
                break;
            case WriteOutcome.ConfirmedByReadBack byReadBack:
                logger.Information(
                    "Write station {Station} {Address:l}: {OldValue:l} -> {NewValue:l} confirmed (reply lost, read back): {Cause:l}",
                    station, address, oldValue, newValue, byReadBack.Cause);
                break;
            case WriteOutcome.NotApplied notApplied:
                logger.Warning(
                    "Write station {Station} {Address:l}: {OldValue:l} -> {NewValue:l} not applied, read back {ReadBack:l}: {Cause:l}",
                    station, address, oldValue, newValue, Format(request.Address, notApplied.ReadBack), notApplied.Cause);
                break;
            case WriteOutcome.Unknown unknown:
                logger.Warning(
                    "Write station {Station} {Address:l}: {OldValue:l} -> {NewValue:l} unknown: {Cause:l}; {Detail:l}",
                    station, address, oldValue, newValue, unknown.Cause, unknown.Detail);
                break;
            case WriteOutcome.Failed failed:
                logger.Warning(
                    "Write station {Station} {Address:l}: {OldValue:l} -> {NewValue:l} failed ({Kind}): {Reason:l}",
                    station, address, oldValue, newValue, failed.Kind, failed.Reason);
                break;
            default:
                throw new ArgumentOutOfRangeException(nameof(outcome), outcome, null);
        }
    }

    /// <summary>Reads back what <see cref="Format"/> wrote ("16#002A", "1"); false for "unknown" or anything else.</summary>
    public static bool TryParse(PlcAddress address, string text, out ImmutableArray<byte> value)
    {
        value = default;
        if (address.Width == AccessWidth.Bit)
        {
            value = text switch { "0" => [0], "1" => [1], _ => default };
            return !value.IsDefault;
        }

        if (!text.StartsWith("16#", StringComparison.Ordinal) || text.Length != 3 + (2 * address.Width.ByteCount()))
        {
            return false;
        }

        try
        {
            value = [.. Convert.FromHexString(text.AsSpan(3))];
            return true;
        }
        catch (FormatException)
        {
            return false;
        }
    }

    public static string Format(PlcAddress address, ImmutableArray<byte> value) =>
        value.IsDefaultOrEmpty ? Unknown
        : address.Width == AccessWidth.Bit ? (value[0] != 0 ? "1" : "0")
        : "16#" + Convert.ToHexString(value.AsSpan());
}
