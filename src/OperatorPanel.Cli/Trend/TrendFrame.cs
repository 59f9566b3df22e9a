using OperatorPanel.Cli.Commands;
using OperatorPanel.Cli.History;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Line;
using OperatorPanel.Core.Polling;
using OperatorPanel.Historian.Reading;

namespace OperatorPanel.Cli.Trend;

/// <summary>
/// What <c>opanel trend</c> shows at one moment: per tag its value now and its trend over the window, drawn as text, and
/// the state of the stations the tags are on.
/// </summary>
internal sealed record TrendFrame(DateTimeOffset From, DateTimeOffset To, IReadOnlyList<TrendPanel> Panels, IReadOnlyList<TrendStation> Stations)
{
    public static TrendFrame Build(
        HistoryReader reader, IReadOnlyList<NamedTag> tags, ILineValues line, Func<Station, StationStatus?> statusOf, DateTimeOffset now, TimeSpan span, int width, int height)
    {
        ArgumentNullException.ThrowIfNull(reader);
        ArgumentNullException.ThrowIfNull(tags);
        ArgumentNullException.ThrowIfNull(line);
        ArgumentNullException.ThrowIfNull(statusOf);
        var from = now - span;
        var spans = reader.Sessions(from, now);
        var histories = reader.Read([.. tags.Select(t => t.Tag)], from, now);
        var panels = tags.Zip(histories, (tag, history) =>
        {
            var series = TrendSeries.Of(history, spans, from, now, liveUntil: now);
            var rows = TrendText.Draw(TrendColumns.Of(series, width), height, out var min, out var max);
            line.TryGetValue(tag.Tag.Station, tag.Tag.Address, out var value);
            var text = value.HasValue ? tag.Tag.Text(value.Raw.AsSpan()) : "-";
            return new TrendPanel(tag.Name, text, value.Quality.ToString().ToLowerInvariant(), min, max, rows, series.Gaps.Count);
        });
        var stations = tags.DistinctBy(t => t.Tag.Station).Select(t =>
        {
            var status = statusOf(t.Tag.Station) ?? StationStatus.Initial(t.Tag.Station);
            return new TrendStation(t.StationName, t.Tag.Station.Address, status.State.ToString().ToLowerInvariant(), LinkFailure.WithoutKind(status.LastError, status.LastErrorKind));
        });
        return new TrendFrame(from, now, [.. panels], [.. stations]);
    }
}

/// <summary>
/// One tag in a frame: its value now, the window's range (null when the window holds no good value: nothing to draw) and
/// the chart's rows (top first).
/// </summary>
internal sealed record TrendPanel(string Name, string Value, string Quality, double? Min, double? Max, IReadOnlyList<string> Rows, int Gaps);
