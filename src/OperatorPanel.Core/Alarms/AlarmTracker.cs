using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Projects;

namespace OperatorPanel.Core.Alarms;

/// <summary>
/// The alarm state machine of every alarm of a project (seed 000 §7: messages shown while a flag bit is set).
/// Only a <see cref="ValueQuality.Good"/> reading moves an alarm: a stale or bad value says nothing about the flag, so
/// the alarm keeps its state until the link reads the bit again (a lost cable neither raises nor clears alarms), and is
/// marked unknown meanwhile (<see cref="AlarmStatus.IsKnown"/>, <see cref="AlarmFlag"/>): a station not read shows
/// "alarms unknown", never "no alarms".
/// Not thread-safe: feed it from one thread (the view model's dispatcher).
/// </summary>
public sealed class AlarmTracker
{
    private readonly TimeProvider _time;
    private readonly List<AlarmStatus> _alarms = [];
    private readonly Dictionary<(Station Station, PlcAddress Flag), int> _index = [];

    public AlarmTracker(PanelProject project, TimeProvider time)
    {
        ArgumentNullException.ThrowIfNull(project);
        ArgumentNullException.ThrowIfNull(time);
        _time = time;
        foreach (var station in project.Stations)
        {
            foreach (var alarm in station.Alarms)
            {
                if (_index.TryAdd((station.Address, alarm.Flag), _alarms.Count))
                {
                    _alarms.Add(new AlarmStatus(station.Name, station.Address, alarm, AlarmState.Cleared, null, null, null));
                }
            }
        }
    }

    /// <summary>Every alarm of the project in project order.</summary>
    public IReadOnlyList<AlarmStatus> Alarms => _alarms;

    public int ActiveCount => _alarms.Count(a => a.IsActive);

    public int UnacknowledgedCount => _alarms.Count(a => a.IsUnacknowledged);

    /// <summary>Alarms whose flag has no good reading now (never read, station offline, read refused).</summary>
    public int UnknownCount => _alarms.Count(a => !a.IsKnown);

    /// <summary>Applies a batch of polled values; returns the transitions they caused, in batch order.</summary>
    public IReadOnlyList<AlarmEvent> Apply(IReadOnlyList<ValueChange> changes)
    {
        ArgumentNullException.ThrowIfNull(changes);
        return [.. changes.Select(c => Apply(c.Station, c.Address, c.Current)).OfType<AlarmEvent>()];
    }

    /// <summary>
    /// Applies one polled value of a flag; returns the transition it caused, or null. A value that is not good makes
    /// the alarm unknown and causes no transition.
    /// </summary>
    public AlarmEvent? Apply(Station station, PlcAddress flag, PolledValue value)
    {
        ArgumentNullException.ThrowIfNull(value);
        if (!_index.TryGetValue((station, flag), out var i))
        {
            return null;
        }

        if (AlarmFlag.Reading(value) is not { } on)
        {
            _alarms[i] = _alarms[i] with { IsKnown = false };
            return null;
        }

        var status = _alarms[i] = _alarms[i] with { IsKnown = true };
        var next = (on, status.State) switch
        {
            (true, AlarmState.Cleared or AlarmState.ClearedUnacknowledged) => Raise(status),
            (false, AlarmState.ActiveUnacknowledged) => status with { State = AlarmState.ClearedUnacknowledged, ClearedAt = Now() },
            (false, AlarmState.ActiveAcknowledged) => status with { State = AlarmState.Cleared, ClearedAt = Now() },
            (true, AlarmState.ActiveUnacknowledged or AlarmState.ActiveAcknowledged) or (false, AlarmState.Cleared or AlarmState.ClearedUnacknowledged) => null,
        };
        return next is null ? null : Record(i, next, on ? AlarmTransition.Raised : AlarmTransition.Cleared);
    }

    /// <summary>Acknowledges one alarm; null when it had nothing to acknowledge (or is not an alarm of the project).</summary>
    public AlarmEvent? Acknowledge(Station station, PlcAddress flag)
    {
        if (!_index.TryGetValue((station, flag), out var i) || !_alarms[i].IsUnacknowledged)
        {
            return null;
        }

        var status = _alarms[i];
        var state = status.State == AlarmState.ActiveUnacknowledged ? AlarmState.ActiveAcknowledged : AlarmState.Cleared;
        return Record(i, status with { State = state, AcknowledgedAt = Now() }, AlarmTransition.Acknowledged);
    }

    /// <summary>Acknowledges every alarm waiting for it, in project order.</summary>
    public IReadOnlyList<AlarmEvent> AcknowledgeAll() =>
        [.. _alarms.Where(a => a.IsUnacknowledged).ToList().Select(a => Acknowledge(a.Station, a.Definition.Flag)!)];

    /// <summary>
    /// Takes up where a previous run left off: replays <paramref name="history"/> (oldest first) so an alarm still waiting
    /// for acknowledgement at shutdown waits again. Entries for alarms the project no longer has are skipped.
    /// </summary>
    public void Restore(IEnumerable<AlarmEvent> history)
    {
        ArgumentNullException.ThrowIfNull(history);
        foreach (var entry in history)
        {
            if (_index.TryGetValue((entry.Station, entry.Flag), out var i))
            {
                _alarms[i] = entry.Transition switch
                {
                    AlarmTransition.Raised => _alarms[i] with { State = entry.State, RaisedAt = entry.At, ClearedAt = null, AcknowledgedAt = null },
                    AlarmTransition.Cleared => _alarms[i] with { State = entry.State, ClearedAt = entry.At },
                    AlarmTransition.Acknowledged => _alarms[i] with { State = entry.State, AcknowledgedAt = entry.At },
                };
            }
        }
    }

    /// <summary>An alarm that needs no acknowledgement is born acknowledged, so it leaves the list when it clears.</summary>
    private AlarmStatus Raise(AlarmStatus status) => status with
    {
        State = status.Definition.AcknowledgementRequired ? AlarmState.ActiveUnacknowledged : AlarmState.ActiveAcknowledged,
        RaisedAt = Now(),
        ClearedAt = null,
        AcknowledgedAt = null,
    };

    private AlarmEvent Record(int index, AlarmStatus next, AlarmTransition transition)
    {
        _alarms[index] = next;
        var at = transition switch
        {
            AlarmTransition.Raised => next.RaisedAt!.Value,
            AlarmTransition.Cleared => next.ClearedAt!.Value,
            AlarmTransition.Acknowledged => next.AcknowledgedAt!.Value,
        };
        return new AlarmEvent(at, next.StationName, next.Station, next.Definition.Flag, transition, next.State, next.Definition.Class, next.Definition.Text);
    }

    private DateTimeOffset Now() => _time.GetUtcNow();
}
