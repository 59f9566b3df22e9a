using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Alarms;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Projects;

namespace OperatorPanel.ViewModels.Tests.Fakes;

/// <summary>A one-station project with three alarms (M0.0 fault, V10.1 warning without acknowledgement, M0.1 warning) and value builders.</summary>
internal static class AlarmProject
{
    public static readonly Station Station = new(2);
    public static readonly PlcAddress Jam = PlcAddress.Parse("M0.0");
    public static readonly PlcAddress LowLevel = PlcAddress.Parse("V10.1");
    public static readonly PlcAddress DoorOpen = PlcAddress.Parse("M0.1");

    public static PanelProject Create()
    {
        var project = StarterProject.Create("Bottling", CpuProfiles.For(CpuModel.Cpu224), Station, "COM3");
        var station = project.Stations[0] with
        {
            Name = "Filler",
            Alarms =
            [
                new AlarmDefinition(Jam, "Conveyor jam, \"infeed\", stop", AlarmClass.Fault, AcknowledgementRequired: true),
                new AlarmDefinition(LowLevel, "Glue level low", AlarmClass.Warning, AcknowledgementRequired: false),
                new AlarmDefinition(DoorOpen, "Guard door open", AlarmClass.Warning, AcknowledgementRequired: true),
            ],
        };
        return project with { Stations = [station] };
    }

    public static ValueChange[] Bit(PlcAddress flag, bool on, ValueQuality quality = ValueQuality.Good, DateTimeOffset at = default)
    {
        var value = new PolledValue(ImmutableArray.Create((byte)(on ? 1 : 0)), at, quality, quality == ValueQuality.Good ? null : "no answer");
        return [new ValueChange(Station, flag, PolledValue.NotRead(at), value)];
    }
}
