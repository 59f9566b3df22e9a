using System.Text.Json.Nodes;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Tests.Projects;

namespace OperatorPanel.Core.Tests.Polling;

public sealed class ProjectBusTests
{
    [Fact]
    public void Of_SampleLine_IsOneBusWatchingEveryInputOutputTagAndAlarm()
    {
        var project = ProjectFile.Load(SampleProject.Path).Project!;

        var bus = ProjectBus.Of(project).Should().ContainSingle().Subject;

        bus.Serial.PortName.Should().Be("COM3");
        bus.WatchedItems().Should().HaveCount(14 + 10 + 11 + 8);
        var plan = bus.Plan();
        plan.Rejected.Should().BeEmpty();
        plan.Frames.Should().OnlyContain(f => f.Station == new Station(2));
        plan.Frames.SelectMany(f => f.Items).Select(i => i.Area).Should().Contain([ProtocolArea.I, ProtocolArea.Q, ProtocolArea.M, ProtocolArea.V]);
    }

    [Fact]
    public void Of_StationsOnTwoPorts_GivesTwoBusesInFileOrder()
    {
        var tree = SampleProject.Tree();
        var stations = tree["stations"]!.AsArray();
        var second = JsonNode.Parse(stations[0]!.ToJsonString())!.AsObject();
        second["name"] = "Capper";
        second["link"]!["port"] = "COM4";
        stations.Add(second);
        var third = JsonNode.Parse(stations[0]!.ToJsonString())!.AsObject();
        third["name"] = "Labeller";
        third["address"] = 3;
        third["link"]!["port"] = "com3";
        stations.Add(third);
        var project = ProjectFile.Parse(tree.ToJsonString()).Project!;

        var buses = ProjectBus.Of(project);

        buses.Select(b => b.Serial.PortName).Should().Equal("COM3", "COM4");
        buses[0].Stations.Select(s => s.Name).Should().Equal("Filler", "Labeller");
        buses[0].StationAt(new Station(3))!.Name.Should().Be("Labeller");
    }
}
