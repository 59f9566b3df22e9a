using OperatorPanel.Core.Projects;

namespace OperatorPanel.Core.Tests.Projects;

/// <summary>A station's "allowStop": off unless the file says true, kept through save and load, a wrong value named.</summary>
public sealed class ProjectFileAllowStopTests
{
    [Fact]
    public void Parse_Sample_AllowsStopForTheDemoFiller()
    {
        ProjectFile.Parse(SampleProject.Text).Project!.Stations[0].AllowStop.Should().BeTrue();
    }

    [Fact]
    public void Parse_FieldMissing_StopIsNotAllowed()
    {
        var tree = SampleProject.Tree();
        tree.Station().Remove("allowStop");

        ProjectFile.Parse(tree.ToJsonString()).Project!.Stations[0].AllowStop.Should().BeFalse();
    }

    [Theory]
    [InlineData(true)]
    [InlineData(false)]
    public void Format_AllowStop_RoundTrips(bool allowStop)
    {
        var project = ProjectFile.Parse(SampleProject.Text).Project!;
        var edited = project with { Stations = [project.Stations[0] with { AllowStop = allowStop }] };

        var text = ProjectFile.Format(edited);
        var reloaded = ProjectFile.Parse(text).Project!;

        text.Should().Contain($"\"allowStop\": {(allowStop ? "true" : "false")}");
        reloaded.Stations[0].AllowStop.Should().Be(allowStop);
        reloaded.Should().BeEquivalentTo(edited, o => o.ComparingRecordsByMembers());
    }

    [Fact]
    public void Parse_AllowStopNotABoolean_NamesTheField()
    {
        BadFile.Expect(t => t.Station()["allowStop"] = "yes", "$.stations[0].allowStop", "expected true or false, found the string \"yes\"");
    }
}
