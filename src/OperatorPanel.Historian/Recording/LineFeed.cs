using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Line;
using OperatorPanel.Core.Polling;

namespace OperatorPanel.Historian.Recording;

/// <summary>
/// The one place the historian meets the line, through its public value surface only: one <see cref="ILineValues"/>
/// subscription per recorded value (the line already polls every project value, so recording adds no exchange on the
/// bus), and each station's status read from the engine once a second (no exchange either). When the line is
/// reorganised, this class is what gets re-pointed.
/// </summary>
public sealed class LineFeed : IDisposable
{
    public static readonly TimeSpan StatusPeriod = TimeSpan.FromSeconds(1);

    private readonly List<IDisposable> _subscriptions = [];
    private readonly ITimer _status;

    public LineFeed(HistoryRecorder recorder, ILineValues values, Func<Station, StationStatus?> statusOf, TimeProvider time)
    {
        ArgumentNullException.ThrowIfNull(recorder);
        ArgumentNullException.ThrowIfNull(values);
        ArgumentNullException.ThrowIfNull(statusOf);
        ArgumentNullException.ThrowIfNull(time);
        foreach (var tag in recorder.Tags)
        {
            var (station, address) = (tag.Station, tag.Address);
            _subscriptions.Add(values.Subscribe(station, address, value => recorder.Record(station, address, value)));
        }

        var stations = recorder.Tags.Select(t => t.Station).Distinct().ToList();
        void SampleStatus()
        {
            foreach (var station in stations)
            {
                StationStatus? status;
                try
                {
                    status = statusOf(station);
                }
                catch (InvalidOperationException)
                {
                    // The line's buses are being replaced (connect, disconnect, an edit) on their owner's thread: the
                    // next second's sample reads the new ones.
                    return;
                }

                recorder.RecordStationState(station, status?.State ?? StationState.Unknown, status?.LastError);
            }
        }

        SampleStatus();
        _status = time.CreateTimer(_ => SampleStatus(), null, StatusPeriod, StatusPeriod);
    }

    public void Dispose()
    {
        _status.Dispose();
        _subscriptions.ForEach(s => s.Dispose());
        _subscriptions.Clear();
    }
}
