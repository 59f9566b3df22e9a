using OperatorPanel.Core.Alarms;
using OperatorPanel.TestKit;
using OperatorPanel.ViewModels.Alarms;
using OperatorPanel.ViewModels.Tests.Fakes;
using static OperatorPanel.ViewModels.Tests.Fakes.AlarmProject;

namespace OperatorPanel.ViewModels.Tests.Alarms;

/// <summary>The alarm sound: repeated while unacknowledged, silenced, louder classes first, off when the project says so.</summary>
public sealed class AlarmAnnunciatorTests : IDisposable
{
    private readonly ManualTimeProvider _clock = new();
    private readonly FakeLineValues _values = new();
    private readonly FakeAlarmSound _sound = new();
    private readonly TempFolder _folder = new();

    public void Dispose() => _folder.Dispose();

    [Fact]
    public void Fault_Unacknowledged_RepeatsEveryThreeSecondsUntilAcknowledged()
    {
        using var alarms = Create();
        _values.Publish(Bit(Jam, on: true));
        _clock.Advance(TimeSpan.FromSeconds(7));

        _sound.Played.Should().Equal("fault", "fault", "fault");
        alarms.Annunciator.IsSounding.Should().BeTrue();

        alarms.AcknowledgeAllCommand.Execute(null);
        _clock.Advance(TimeSpan.FromSeconds(10));

        _sound.Played.Should().Equal("fault", "fault", "fault", "stop");
        alarms.Annunciator.IsSounding.Should().BeFalse();
    }

    [Fact]
    public void Silence_QuietsThePendingAlarmsButANewRaiseSoundsAgain()
    {
        using var alarms = Create();
        _values.Publish(Bit(Jam, on: true));
        alarms.Annunciator.SilenceCommand.Execute(null);
        _clock.Advance(TimeSpan.FromSeconds(10));
        _sound.Played.Should().Equal("fault", "stop");

        _values.Publish(Bit(DoorOpen, on: true));

        _sound.Played.Should().Equal("fault", "stop", "warning");
        alarms.Annunciator.Sounding.Should().Be(AlarmClass.Warning, "the silenced jam stays quiet until it is raised again");
    }

    [Fact]
    public void Fault_RaisedWhileAWarningSounds_TakesOverAtOnce()
    {
        using var alarms = Create();
        _values.Publish(Bit(DoorOpen, on: true));
        _clock.Advance(TimeSpan.FromSeconds(1));

        _values.Publish(Bit(Jam, on: true));

        _sound.Played.Should().Equal("warning", "fault");
        alarms.Annunciator.Sounding.Should().Be(AlarmClass.Fault);
    }

    [Fact]
    public void AlarmWithoutAcknowledgement_PlaysOnceWhenRaised()
    {
        using var alarms = Create();

        _values.Publish(Bit(LowLevel, on: true));
        _clock.Advance(TimeSpan.FromMinutes(1));

        _sound.Played.Should().Equal("warning");
        alarms.Annunciator.IsSounding.Should().BeFalse();
    }

    [Fact]
    public void ProjectWithoutAlarmSound_NeverPlays()
    {
        using var alarms = Create(sound: false);

        _values.Publish([.. Bit(Jam, on: true), .. Bit(LowLevel, on: true)]);
        _clock.Advance(TimeSpan.FromMinutes(1));

        _sound.Played.Should().BeEmpty();
        alarms.Annunciator.SilenceCommand.CanExecute(null).Should().BeFalse();
    }

    private AlarmsViewModel Create(bool sound = true)
    {
        var alarms = new AlarmsViewModel(AlarmProject.Create() with { AlarmSound = sound }, null, _values, _clock, new AlarmServices(new ScriptedFileDialogs(), _sound, null, _folder.Path, "maria"));
        alarms.StartAsync().IsCompletedSuccessfully.Should().BeTrue();
        return alarms;
    }
}
