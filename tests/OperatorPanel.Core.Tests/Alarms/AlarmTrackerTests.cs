using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Alarms;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Projects;
using OperatorPanel.TestKit;

namespace OperatorPanel.Core.Tests.Alarms;

public sealed class AlarmTrackerTests
{
    private static readonly Station Filler = new(2);
    private static readonly PlcAddress Jam = PlcAddress.Parse("M0.0");
    private readonly ManualTimeProvider _clock = new();

    [Fact]
    public void Alarms_FlagNeverRead_AreUnknownNotCleared()
    {
        var tracker = new AlarmTracker(Project(), _clock);

        tracker.Alarms.Should().ContainSingle().Which.IsKnown.Should().BeFalse();
        tracker.UnknownCount.Should().Be(1);
    }

    [Fact]
    public void Apply_GoodReading_MakesTheAlarmKnown()
    {
        var tracker = new AlarmTracker(Project(), _clock);

        tracker.Apply(Filler, Jam, Good(on: false));

        tracker.Alarms[0].IsKnown.Should().BeTrue();
        tracker.Alarms[0].State.Should().Be(AlarmState.Cleared);
        tracker.UnknownCount.Should().Be(0);
    }

    [Theory]
    [InlineData(ValueQuality.Stale)]
    [InlineData(ValueQuality.Bad)]
    public void Apply_ReadingTurnsUntrusted_AlarmBecomesUnknownAndKeepsItsState(ValueQuality quality)
    {
        var tracker = new AlarmTracker(Project(), _clock);
        tracker.Apply(Filler, Jam, Good(on: true));

        var transition = tracker.Apply(Filler, Jam, Good(on: true) with { Quality = quality, Error = "no answer" });

        transition.Should().BeNull("an unknown flag neither raises nor clears");
        tracker.Alarms[0].IsKnown.Should().BeFalse();
        tracker.Alarms[0].State.Should().Be(AlarmState.ActiveUnacknowledged, "the operator still owes the acknowledgement");
        tracker.UnknownCount.Should().Be(1);
    }

    [Theory]
    [InlineData(ValueQuality.Good, true, true)]
    [InlineData(ValueQuality.Good, false, false)]
    [InlineData(ValueQuality.Stale, true, null)]
    [InlineData(ValueQuality.Bad, false, null)]
    public void Reading_OnlyAGoodValueSaysWhetherTheFlagIsSet(ValueQuality quality, bool bit, bool? expected)
    {
        var value = Good(bit) with { Quality = quality };

        AlarmFlag.Reading(value).Should().Be(expected);
        AlarmFlag.Reading(null).Should().BeNull();
        AlarmFlag.Reading(PolledValue.NotRead(default)).Should().BeNull();
    }

    private static PolledValue Good(bool on) => PolledValue.Good(ImmutableArray.Create((byte)(on ? 1 : 0)), default);

    private static PanelProject Project()
    {
        var project = StarterProject.Create("Line", CpuProfiles.For(CpuModel.Cpu224), Filler, "COM3");
        var station = project.Stations[0] with { Alarms = [new AlarmDefinition(Jam, "Conveyor jam", AlarmClass.Fault, AcknowledgementRequired: true)] };
        return project with { Stations = [station] };
    }
}
