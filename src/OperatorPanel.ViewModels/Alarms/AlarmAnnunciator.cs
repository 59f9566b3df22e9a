using CommunityToolkit.Mvvm.ComponentModel;
using CommunityToolkit.Mvvm.Input;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Alarms;
using OperatorPanel.ViewModels.Services;

namespace OperatorPanel.ViewModels.Alarms;

/// <summary>
/// The alarm sound: while an alarm waits for acknowledgement and nobody silenced it, the tone of the most serious class
/// among those alarms plays at once and then repeats (a fault every 3 s, a warning every 10 s; a notice plays once), until
/// the alarms are acknowledged or the operator presses Silence. Silence quiets the alarms pending now; an alarm raised
/// after it sounds again. An alarm that needs no acknowledgement plays its tone once when raised. Off when the project
/// says <c>"alarmSound": false</c>.
/// </summary>
public sealed partial class AlarmAnnunciator : ObservableObject, IDisposable
{
    private readonly IAlarmSound _sound;
    private readonly ITimer _repeat;
    private readonly HashSet<(Station, PlcAddress, DateTimeOffset?)> _silenced = [];
    private readonly HashSet<(Station, PlcAddress, DateTimeOffset?)> _announced = [];
    private IReadOnlyList<AlarmStatus> _alarms = [];
    private DateTimeOffset _lastPlayed;

    public AlarmAnnunciator(IAlarmSound sound, TimeProvider time, bool enabled)
    {
        ArgumentNullException.ThrowIfNull(sound);
        ArgumentNullException.ThrowIfNull(time);
        (_sound, Time, IsEnabled) = (sound, time, enabled);
        _repeat = time.CreateTimer(_ => Tick(), null, Timeout.InfiniteTimeSpan, Timeout.InfiniteTimeSpan);
    }

    /// <summary>The project's "alarmSound".</summary>
    public bool IsEnabled { get; }

    /// <summary>The class whose tone is sounding (repeating); null when quiet.</summary>
    [ObservableProperty]
    [NotifyPropertyChangedFor(nameof(IsSounding))]
    [NotifyCanExecuteChangedFor(nameof(SilenceCommand))]
    public partial AlarmClass? Sounding { get; private set; }

    public bool IsSounding => Sounding is not null;

    private TimeProvider Time { get; }

    public static TimeSpan RepeatPeriod(AlarmClass alarmClass) => alarmClass switch
    {
        AlarmClass.Fault => TimeSpan.FromSeconds(3),
        AlarmClass.Warning => TimeSpan.FromSeconds(10),
        AlarmClass.Information => Timeout.InfiniteTimeSpan,
    };

    /// <summary>The alarms as they stand now (after a raise, clear or acknowledgement): the sound follows them.</summary>
    public void Update(IReadOnlyList<AlarmStatus> alarms)
    {
        ArgumentNullException.ThrowIfNull(alarms);
        _alarms = alarms;
        // A silenced raise that has been acknowledged or raised again is forgotten: the next raise sounds.
        _silenced.RemoveWhere(key => !alarms.Any(a => a.IsUnacknowledged && Key(a) == key));
        AnnounceNewRaises(alarms);
        var loudest = Audible().Select(a => a.Definition.Class).DefaultIfEmpty().Min();
        AlarmClass? next = Audible().Any() ? loudest : null;
        if (next == Sounding)
        {
            return;
        }

        var louder = next is { } n && (Sounding is not { } now || n < now);
        Sounding = next;
        if (next is null)
        {
            _repeat.Change(Timeout.InfiniteTimeSpan, Timeout.InfiniteTimeSpan);
            _sound.Stop();
        }
        else if (louder)
        {
            Play();
        }
    }

    public void Dispose()
    {
        _repeat.Dispose();
        if (Sounding is not null)
        {
            _sound.Stop();
        }
    }

    [RelayCommand(CanExecute = nameof(IsSounding))]
    private void Silence()
    {
        foreach (var alarm in Audible().ToList())
        {
            _silenced.Add(Key(alarm));
        }

        Update(_alarms);
    }

    private IEnumerable<AlarmStatus> Audible() =>
        IsEnabled ? _alarms.Where(a => a.IsUnacknowledged && !_silenced.Contains(Key(a))) : [];

    /// <summary>A raise of an alarm that needs no acknowledgement: its tone once, unless a repeating tone already sounds.</summary>
    private void AnnounceNewRaises(IReadOnlyList<AlarmStatus> alarms)
    {
        var fresh = alarms.Where(a => !a.Definition.AcknowledgementRequired && a.IsActive && _announced.Add(Key(a))).ToList();
        _announced.RemoveWhere(key => !alarms.Any(a => a.IsActive && Key(a) == key));
        if (IsEnabled && fresh.Count > 0 && Sounding is null)
        {
            _sound.Play(fresh.Min(a => a.Definition.Class));
        }
    }

    private void Play()
    {
        if (Sounding is not { } alarmClass)
        {
            return;
        }

        _sound.Play(alarmClass);
        _lastPlayed = Time.GetUtcNow();
        var period = RepeatPeriod(alarmClass);
        _repeat.Change(period, period);
    }

    private void Tick()
    {
        if (Sounding is { } alarmClass && Time.GetUtcNow() - _lastPlayed >= RepeatPeriod(alarmClass))
        {
            Play();
        }
    }

    private static (Station, PlcAddress, DateTimeOffset?) Key(AlarmStatus alarm) => (alarm.Station, alarm.Definition.Flag, alarm.RaisedAt);
}
