using System.Globalization;
using CommunityToolkit.Mvvm.ComponentModel;
using CommunityToolkit.Mvvm.Input;
using OperatorPanel.Historian.Reading;

namespace OperatorPanel.ViewModels.Trends;

/// <summary>
/// The window of time shown: live (the last <see cref="LiveSpan"/>, moving on every second) or fixed (a look back, or
/// where zooming and panning left it), the cursor, and what the view's mouse asks (<see cref="Zoom"/>, <see cref="Pan"/>,
/// <see cref="PointAt"/>, each in fractions of the plot's width so the view needs no time arithmetic).
/// </summary>
public sealed partial class TrendsViewModel
{
    public static readonly TimeSpan MinimumSpan = TimeSpan.FromSeconds(10);
    public static readonly TimeSpan MaximumSpan = TimeSpan.FromDays(31);

    public DateTimeOffset From { get; private set; }

    public DateTimeOffset To { get; private set; }

    /// <summary>Live: the window ends now and scrolls with time.</summary>
    public bool IsLive => Range == TrendRange.Live;

    [ObservableProperty]
    [NotifyPropertyChangedFor(nameof(IsLive))]
    [NotifyCanExecuteChangedFor(nameof(BackToLiveCommand))]
    public partial TrendRange Range { get; set; } = TrendRange.Live;

    /// <summary>How much of the recent past the live window shows (zooming while live changes it).</summary>
    [ObservableProperty]
    public partial TimeSpan LiveSpan { get; private set; } = DefaultLiveSpan;

    /// <summary>With <see cref="TrendRange.Custom"/>: the start, in the panel's local time.</summary>
    [ObservableProperty]
    public partial DateTime? CustomFrom { get; set; }

    /// <summary>With <see cref="TrendRange.Custom"/>: the end, local time; empty: now.</summary>
    [ObservableProperty]
    public partial DateTime? CustomTo { get; set; }

    /// <summary>The time the cursor reads; null without one.</summary>
    public DateTimeOffset? Cursor { get; private set; }

    /// <summary>
    /// Zooms by <paramref name="factor"/> (below 1 in, above 1 out) around <paramref name="anchor"/>, the point of the
    /// plot's width under the mouse (0 left, 1 right). Live, the right edge stays now and only the span changes.
    /// </summary>
    public void Zoom(double factor, double anchor)
    {
        if (!(factor > 0) || !double.IsFinite(factor))
        {
            return;
        }

        var span = Clamp((To - From) * factor);
        if (IsLive)
        {
            LiveSpan = span;
        }
        else
        {
            var at = From + ((To - From) * Math.Clamp(anchor, 0, 1));
            (From, To) = (at - (span * Math.Clamp(anchor, 0, 1)), at + (span * (1 - Math.Clamp(anchor, 0, 1))));
        }

        _ = RefreshAsync();
    }

    /// <summary>Moves the window by <paramref name="fraction"/> of its width (positive: later). Leaves live mode; never past now.</summary>
    public void Pan(double fraction)
    {
        if (!double.IsFinite(fraction) || fraction == 0)
        {
            return;
        }

        var shift = (To - From) * fraction;
        var now = _time.GetUtcNow();
        if (To + shift > now)
        {
            shift = now - To;
        }

        Freeze();
        (From, To) = (From + shift, To + shift);
        _ = RefreshAsync();
    }

    /// <summary>Puts the cursor at <paramref name="fraction"/> of the plot's width; each picked tag reads its value there.</summary>
    public void PointAt(double fraction)
    {
        Cursor = From + ((To - From) * Math.Clamp(fraction, 0, 1));
        UpdateCursor();
        Plot = Plot with { Cursor = Cursor };
    }

    [RelayCommand]
    private void ClearCursor()
    {
        Cursor = null;
        UpdateCursor();
        Plot = Plot with { Cursor = null };
    }

    [RelayCommand]
    private void ZoomIn() => Zoom(0.5, 1);

    [RelayCommand]
    private void ZoomOut() => Zoom(2, 1);

    [RelayCommand(CanExecute = nameof(IsNotLive))]
    private void BackToLive() => Range = TrendRange.Live;

    private bool IsNotLive() => !IsLive;

    partial void OnRangeChanged(TrendRange value)
    {
        var now = _time.GetUtcNow();
        switch (value)
        {
            case TrendRange.Live:
                (From, To) = (now - LiveSpan, now);
                break;
            case TrendRange.LastHour:
                (From, To) = (now.AddHours(-1), now);
                break;
            case TrendRange.Shift:
                (From, To) = (now.AddHours(-8), now);
                break;
            case TrendRange.Day:
                (From, To) = (now.AddDays(-1), now);
                break;
            case TrendRange.Custom:
                ApplyCustom(now);
                break;
        }

        _ = RefreshAsync();
    }

    partial void OnCustomFromChanged(DateTime? value) => ReapplyCustom();

    partial void OnCustomToChanged(DateTime? value) => ReapplyCustom();

    private void ReapplyCustom()
    {
        if (Range == TrendRange.Custom)
        {
            ApplyCustom(_time.GetUtcNow());
            _ = RefreshAsync();
        }
    }

    /// <summary>From CustomFrom (default an hour before the end) to CustomTo (default now), local times.</summary>
    private void ApplyCustom(DateTimeOffset now)
    {
        var to = Local(CustomTo) ?? now;
        var from = Local(CustomFrom) ?? to.AddHours(-1);
        (From, To) = from < to ? (from, to) : (to.AddHours(-1), to);
    }

    /// <summary>Out of live mode, keeping the window where it is.</summary>
    private void Freeze()
    {
        if (IsLive)
        {
            var (from, to) = (From, To);
            Range = TrendRange.Custom;
            (From, To) = (from, to);
        }
    }

    private void UpdateCursor()
    {
        CursorTimeText = Cursor is { } at ? TimeZoneInfo.ConvertTime(at, _time.LocalTimeZone).ToString("yyyy-MM-dd HH:mm:ss", CultureInfo.InvariantCulture) : string.Empty;
        foreach (var tag in Tags)
        {
            var lane = Plot.Lanes.FirstOrDefault(l => l.Name == tag.Name);
            tag.CursorText = Cursor is not { } time || lane is null ? string.Empty : Reading(lane, time, tag);
        }
    }

    private static string Reading(TrendLane lane, DateTimeOffset at, TrendTagViewModel tag)
    {
        if (lane.Gaps.FirstOrDefault(g => g.From <= at && at < g.To) is { } gap)
        {
            return gap.Kind switch
            {
                TrendGapKind.NotRecorded => "not recorded",
                TrendGapKind.Stale => "stale",
                TrendGapKind.Bad => "bad",
            };
        }

        var point = lane.Segments.SelectMany(s => s.Points).LastOrDefault(p => p.At <= at);
        if (point == default)
        {
            return "not recorded";
        }

        var text = tag.IsBit ? (point.Value != 0 ? "1" : "0") : point.Value.ToString("0.###", CultureInfo.InvariantCulture);
        return $"{text} (good)";
    }

    private DateTimeOffset? Local(DateTime? at) =>
        at is { } t ? new DateTimeOffset(DateTime.SpecifyKind(t, DateTimeKind.Unspecified), _time.LocalTimeZone.GetUtcOffset(t)) : null;

    private static TimeSpan Clamp(TimeSpan span) => span < MinimumSpan ? MinimumSpan : span > MaximumSpan ? MaximumSpan : span;
}
