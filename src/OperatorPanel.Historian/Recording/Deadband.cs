using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Projects;

namespace OperatorPanel.Historian.Recording;

/// <summary>
/// Whether a tag's new value is worth a row: always when there is no row yet, when its quality changed or it gained or
/// lost its value; for a bit or a code, when it changed at all; for a number, when it moved more than the deadband from the
/// value last recorded (the tag's own, or the project's percentage of that value, as HMI logs call a relative hysteresis).
/// A deadband of 0 records every change.
/// </summary>
internal static class Deadband
{
    public static bool Passes(RecordedTag tag, HistorySettings settings, PolledValue? last, PolledValue next)
    {
        if (last is null || last.Quality != next.Quality || last.HasValue != next.HasValue)
        {
            return true;
        }

        if (!next.HasValue || last.Raw.AsSpan().SequenceEqual(next.Raw.AsSpan()))
        {
            return false;
        }

        if (!tag.IsNumeric)
        {
            return true;
        }

        var before = Number(tag, last);
        var now = Number(tag, next);
        var band = tag.Deadband ?? settings.DeadbandPercent / 100 * Math.Abs(before);
        // NaN (a REAL holding no number) compares false everywhere: any step to or from it is recorded.
        return !(Math.Abs(now - before) <= band);
    }

    private static double Number(RecordedTag tag, PolledValue value) => TagValue.ToNumber(TagValue.ToStored(value.Raw), tag.Address, tag.Format);
}
