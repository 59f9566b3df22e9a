using CommunityToolkit.Mvvm.ComponentModel;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Alarms;

namespace OperatorPanel.ViewModels.Alarms;

/// <summary>One alarm of the project as the alarm window shows it; times are in the TimeProvider's local zone.</summary>
public sealed class AlarmRowViewModel : ObservableObject
{
    private readonly TimeZoneInfo _zone;
    private AlarmStatus _status;

    internal AlarmRowViewModel(AlarmStatus status, TimeZoneInfo zone)
    {
        _status = status;
        _zone = zone;
    }

    public string StationName => _status.StationName;

    public Station Station => _status.Station;

    public string Flag => _status.Definition.Flag.ToString();

    public string Text => _status.Definition.Text;

    public AlarmClass Class => _status.Definition.Class;

    public AlarmState State => _status.State;

    /// <summary>
    /// "active unacknowledged", as the operator reads it. An alarm that needs no acknowledgement reads "active" (not
    /// "active acknowledged": nobody acknowledged it), and one never raised (in this session or the loaded history) reads
    /// "not raised". An alarm whose flag has no good reading reads "unknown", with the last known state when there is
    /// one to remember ("unknown (was active unacknowledged)").
    /// </summary>
    public string StateText => _status.IsKnown
        ? KnownStateText
        : _status.State == AlarmState.Cleared ? "unknown" : $"unknown (was {KnownStateText})";

    /// <summary>False while the flag has no good reading (never read, station offline): the view greys the row.</summary>
    public bool IsKnown => _status.IsKnown;

    private string KnownStateText => _status switch
    {
        { RaisedAt: null, State: AlarmState.Cleared } => "not raised",
        { Definition.AcknowledgementRequired: false, State: AlarmState.ActiveAcknowledged } => "active",
        _ => AlarmCsv.Words(_status.State.ToString()),
    };

    public DateTimeOffset? RaisedAt => Local(_status.RaisedAt);

    public DateTimeOffset? ClearedAt => Local(_status.ClearedAt);

    public DateTimeOffset? AcknowledgedAt => Local(_status.AcknowledgedAt);

    public bool IsActive => _status.IsActive;

    public bool IsUnacknowledged => _status.IsUnacknowledged;

    public bool IsPending => _status.IsPending;

    internal AlarmStatus Status => _status;

    internal void Update(AlarmStatus status)
    {
        if (status == _status)
        {
            return;
        }

        _status = status;
        foreach (var name in new[]
        {
            nameof(State), nameof(StateText), nameof(RaisedAt), nameof(ClearedAt), nameof(AcknowledgedAt),
            nameof(IsActive), nameof(IsUnacknowledged), nameof(IsPending), nameof(IsKnown),
        })
        {
            OnPropertyChanged(name);
        }
    }

    private DateTimeOffset? Local(DateTimeOffset? at) => at is { } t ? TimeZoneInfo.ConvertTime(t, _zone) : null;
}
