using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Projects;

namespace OperatorPanel.Historian.Recording;

/// <summary>
/// Decides what of a project's values becomes a row (<see cref="Deadband"/>, and a periodic sample of every value each
/// <see cref="HistorySettings.SamplePeriod"/> so a flat line is visible) and queues it on the writer. Fed from any thread
/// (the panel's UI thread, each bus's polling loop in the CLI); the work per value is a look-up and a comparison, so the
/// line it listens to is never slowed.
/// </summary>
public sealed class HistoryRecorder : IDisposable
{
    private readonly Lock _gate = new();
    private readonly Dictionary<(Station, PlcAddress), TagState> _tags = [];
    private readonly Dictionary<Station, StationState> _stations = [];
    private readonly HistoryWriter _writer;
    private readonly HistorySettings _settings;
    private readonly TimeProvider _time;
    private readonly ITimer _sampler;
    private readonly TimeSpan _tick;

    internal HistoryRecorder(PanelProject project, HistoryWriter writer, TimeProvider time)
    {
        ArgumentNullException.ThrowIfNull(project);
        (_writer, _settings, _time) = (writer, project.History, time);
        Tags = project.History.Enabled ? RecordedTag.Of(project) : [];
        foreach (var tag in Tags)
        {
            _tags[(tag.Station, tag.Address)] = new TagState(tag);
        }

        _tick = TimeSpan.FromTicks(Math.Max(TimeSpan.TicksPerSecond, _settings.SamplePeriod.Ticks / 4));
        _sampler = time.CreateTimer(_ => SampleFlatValues(), null, _tick, _tick);
    }

    /// <summary>What is recorded: every I/O symbol and recorded tag (none when the project turned history off).</summary>
    public IReadOnlyList<RecordedTag> Tags { get; }

    /// <summary>A value of the line (the first one of a subscription included); ignored for values not recorded.</summary>
    public void Record(Station station, PlcAddress address, PolledValue value)
    {
        ArgumentNullException.ThrowIfNull(value);
        if (!_tags.TryGetValue((station, address), out var state))
        {
            return;
        }

        lock (_gate)
        {
            state.Seen = value;
            if (!Deadband.Passes(state.Tag, _settings, state.Recorded, value))
            {
                return;
            }

            // A good value carries its read time; a stale one keeps its last good read's, so it is stamped now instead.
            Store(state, value, value.Quality == ValueQuality.Good ? value.Timestamp : _time.GetUtcNow());
        }
    }

    /// <summary>A station's state; a row only when it changed.</summary>
    public void RecordStationState(Station station, StationState state, string? error)
    {
        lock (_gate)
        {
            if (_stations.TryGetValue(station, out var last) && last == state)
            {
                return;
            }

            _stations[station] = state;
        }

        _writer.Enqueue(new StationStateRow(station, _time.GetUtcNow(), state, error));
    }

    public void Dispose() => _sampler.Dispose();

    /// <summary>
    /// Each value that would have no row for longer than a sample period by the next tick gets one now, so a trend shows
    /// it held (only values that exist): rows of a flat value are never more than a sample period apart.
    /// </summary>
    private void SampleFlatValues()
    {
        lock (_gate)
        {
            var now = _time.GetUtcNow();
            foreach (var state in _tags.Values)
            {
                if (state.Seen is { HasValue: true } seen && now - state.RecordedAt > _settings.SamplePeriod - _tick)
                {
                    Store(state, seen, now);
                }
            }
        }
    }

    private void Store(TagState state, PolledValue value, DateTimeOffset at)
    {
        // One row per millisecond and tag, in order: a change stamped at or before the last row moves just after it.
        if (at <= state.RecordedAt)
        {
            at = state.RecordedAt.AddMilliseconds(1);
        }

        state.Recorded = value;
        state.RecordedAt = at;
        _writer.Enqueue(new SampleRow(state.Tag, at, value.HasValue ? TagValue.ToStored(value.Raw) : null, value.Quality));
    }

    private sealed class TagState(RecordedTag tag)
    {
        public RecordedTag Tag { get; } = tag;

        public PolledValue? Seen { get; set; }

        public PolledValue? Recorded { get; set; }

        public DateTimeOffset RecordedAt { get; set; } = DateTimeOffset.MinValue;
    }
}
