using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Core.Tests.Projects;

/// <summary>
/// A station with "compact": true and "allowStop": true: the compact handler has no STOP, so the contradiction is a
/// problem of its own, named with the station, both properties and the two ways out. The file still loads: the panel
/// reads and writes such a station; generate and project check refuse it.
/// </summary>
public sealed class CompactStopTests
{
    private const string Message = "Filler (station 2) has \"compact\": true and \"allowStop\": true, but a compact handler has no STOP: "
        + "it would be generated without the STOP that is allowed; set \"compact\": false for the full handler with STOP, or set "
        + "\"allowStop\": false for the compact handler without it";

    [Fact]
    public void Problems_CompactStationWithAllowStop_NamesTheStationBothPropertiesAndBothWaysOut()
    {
        var tree = SampleProject.Tree();
        tree.Station()["compact"] = true;
        var loaded = ProjectFile.Parse(tree.ToJsonString());

        loaded.Ok.Should().BeTrue("the panel opens such a project: it reads and writes the station as any other");
        CompactStop.Problems(loaded.Project!).Should().Equal(new ProjectFileError("$.stations[0]", Message));
    }

    [Theory]
    [InlineData(true, false)]
    [InlineData(false, true)]
    [InlineData(false, false)]
    public void Problems_OneOrNeitherSetting_None(bool compact, bool allowStop)
    {
        var project = ProjectFile.Parse(SampleProject.Text).Project!;
        var edited = project with { Stations = [project.Stations[0] with { Compact = compact, AllowStop = allowStop }] };

        CompactStop.Problems(edited).Should().BeEmpty();
    }

    [Fact]
    public void Problems_SecondStationOnly_PointsAtThatStation()
    {
        var project = ProjectFile.Parse(SampleProject.Text).Project!;
        var second = project.Stations[0] with { Name = "Capper", Address = new Core.Addressing.Station(3), Compact = true, AllowStop = true };
        var edited = project with { Stations = [project.Stations[0] with { AllowStop = false }, second] };

        CompactStop.Problems(edited).Should().ContainSingle().Which.Should().Match<ProjectFileError>(
            e => e.Location == "$.stations[1]" && e.Message.StartsWith("Capper (station 3) has \"compact\": true", StringComparison.Ordinal));
    }

    [Fact]
    public void Problems_PpiStation_NoneSinceItRunsNoHandler()
    {
        var project = ProjectFile.Parse(SampleProject.Text).Project!;
        var ppi = project.Stations[0] with { Compact = true, Link = project.Stations[0].Link with { Protocol = LinkProtocol.Ppi } };

        CompactStop.Problems(project with { Stations = [ppi] }).Should().BeEmpty();
    }
}
