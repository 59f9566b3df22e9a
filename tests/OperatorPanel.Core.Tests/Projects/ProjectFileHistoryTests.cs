using System.Text.Json.Nodes;
using OperatorPanel.Core.Projects;

namespace OperatorPanel.Core.Tests.Projects;

/// <summary>
/// The historian's settings in the project file ("history", "alarmSound", a tag's "record" and "deadband"): optional, so
/// a file written before them loads with the defaults; kept through save and load; a wrong value named where it is.
/// </summary>
public sealed class ProjectFileHistoryTests
{
    [Fact]
    public void Parse_FileWithoutHistorySettings_LoadsWithTheDefaults()
    {
        var tree = SampleProject.Tree();
        tree.Remove("history");
        tree.Remove("alarmSound");
        foreach (var tag in tree.Station()["tags"]!.AsArray())
        {
            tag!.AsObject().Remove("record");
        }

        var project = ProjectFile.Parse(tree.ToJsonString()).Project!;

        project.History.Should().Be(HistorySettings.Default);
        project.AlarmSound.Should().BeTrue();
        project.Stations[0].Tags.Should().OnlyContain(t => t.Recorded && t.Deadband == null);
    }

    [Fact]
    public void Format_EditedSettings_RoundTrip()
    {
        var project = ProjectFile.Parse(SampleProject.Text).Project!;
        var station = project.Stations[0];
        var tags = station.Tags.SetItem(0, station.Tags[0] with { Recorded = false }).SetItem(1, station.Tags[1] with { Deadband = 2.5 });
        var edited = project with
        {
            History = new HistorySettings(false, 1.25, TimeSpan.FromSeconds(30), 7, 50),
            AlarmSound = false,
            Stations = [station with { Tags = tags }],
        };

        var text = ProjectFile.Format(edited);
        var reloaded = ProjectFile.Parse(text).Project!;

        text.Should().Contain("\"deadbandPercent\": 1.25").And.Contain("\"deadband\": 2.5").And.Contain("\"alarmSound\": false");
        reloaded.History.Should().Be(edited.History);
        reloaded.AlarmSound.Should().BeFalse();
        reloaded.Stations[0].Tags[0].Recorded.Should().BeFalse();
        reloaded.Stations[0].Tags[1].Deadband.Should().Be(2.5);
    }

    [Fact]
    public void Parse_DeadbandWrittenNull_MeansTheProjectDeadband()
    {
        var tree = SampleProject.Tree();
        tree.Station()["tags"]![0]!["deadband"] = null;

        ProjectFile.Parse(tree.ToJsonString()).Project!.Stations[0].Tags[0].Deadband.Should().BeNull();
    }

    [Theory]
    [InlineData("deadbandPercent", "150", "$.history.deadbandPercent", "deadband 150 % is outside 0-100 %")]
    [InlineData("samplePeriodS", "0", "$.history.samplePeriodS", "0 s is outside 1-86400 s")]
    [InlineData("retentionDays", "0", "$.history.retentionDays", "0 days is outside 1-3650 days")]
    [InlineData("maxSizeMb", "5", "$.history.maxSizeMb", "5 MB is outside 10-100000 MB")]
    [InlineData("enabled", "\"yes\"", "$.history.enabled", "expected true or false, found the string \"yes\"")]
    [InlineData("keepDays", "3", "$.history.keepDays", "unknown property 'keepDays'; expected enabled, deadbandPercent, samplePeriodS, retentionDays, maxSizeMb")]
    public void Parse_BadHistorySetting_NamesIt(string name, string json, string location, string message)
    {
        BadFile.Expect(t => t["history"]![name] = JsonNode.Parse(json), location, message);
    }

    [Fact]
    public void Parse_NegativeTagDeadband_NamesIt()
    {
        BadFile.Expect(t => t.Station()["tags"]![1]!["deadband"] = -1, "$.stations[0].tags[1].deadband", "a deadband cannot be negative; 0 records every change");
    }

    [Fact]
    public void Parse_TagDeadbandNotANumber_NamesIt()
    {
        BadFile.Expect(t => t.Station()["tags"]![1]!["deadband"] = "5", "$.stations[0].tags[1].deadband", "expected a number, found the string \"5\"");
    }
}
