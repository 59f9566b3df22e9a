using OperatorPanel.Core.Projects;

namespace OperatorPanel.Core.Tests.Projects;

/// <summary>
/// A station's "compact" (the compact protocol 3 handler): off unless the file says true, written only when set so an
/// older project file loads and saves unchanged, kept through save and load, a wrong value named.
/// </summary>
public sealed class ProjectFileCompactTests
{
    [Fact]
    public void Parse_FileWithoutTheField_FullHandlerAndSavedByteForByteAsBefore()
    {
        var project = ProjectFile.Parse(SampleProject.Text).Project!;

        project.Stations[0].Compact.Should().BeFalse();
        SampleProject.Text.Should().NotContain("\"compact\"");
        ProjectFile.Format(project).Should().NotContain("\"compact\"", "a project without the compact handler keeps the file it always had");
    }

    [Fact]
    public void Format_Compact_WrittenAndRoundTrips()
    {
        var project = ProjectFile.Parse(SampleProject.Text).Project!;
        var edited = project with { Stations = [project.Stations[0] with { Compact = true }] };

        var text = ProjectFile.Format(edited);
        var reloaded = ProjectFile.Parse(text).Project!;

        text.Should().Contain("\"compact\": true");
        reloaded.Stations[0].Compact.Should().BeTrue();
        reloaded.Should().BeEquivalentTo(edited, o => o.ComparingRecordsByMembers());
    }

    [Fact]
    public void Parse_CompactNotABoolean_NamesTheField()
    {
        BadFile.Expect(t => t.Station()["compact"] = "yes", "$.stations[0].compact", "expected true or false, found the string \"yes\"");
    }
}
