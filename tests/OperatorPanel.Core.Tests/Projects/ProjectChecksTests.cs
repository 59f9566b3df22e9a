using OperatorPanel.Core.Projects;

namespace OperatorPanel.Core.Tests.Projects;

/// <summary>
/// What a project that loads may still have wrong, as project check lists it: a compact station with STOP, and a writable
/// tag whose every write the write rules refuse (in the handler's own V bytes, or sharing bytes with a read-only tag),
/// each at its place in the file.
/// </summary>
public sealed class ProjectChecksTests
{
    [Fact]
    public void Problems_SampleProject_None()
    {
        ProjectChecks.Problems(ProjectFile.Parse(SampleProject.Text).Project!).Should().BeEmpty();
    }

    [Fact]
    public void Problems_WritableTagInTheHandlersOwnVBytes_LoadsAndIsAProblemAtTheTag()
    {
        var tree = SampleProject.Tree();
        var tags = tree.Station()["tags"]!.AsArray();
        tags.Add(new System.Text.Json.Nodes.JsonObject { ["symbol"] = "Spare", ["address"] = "VW8000", ["writable"] = true });
        var loaded = ProjectFile.Parse(tree.ToJsonString());

        loaded.Ok.Should().BeTrue("the panel opens such a project and refuses the tag's writes when they are tried");
        ProjectChecks.Problems(loaded.Project!).Should().ContainSingle().Which.Should().Be(new ProjectFileError(
            $"$.stations[0].tags[{tags.Count - 1}]",
            "tag Spare (VW8000) is writable, but VW8000 is in the handler's own V bytes VB7586-VB8191 (where generate puts the full handler's "
            + "buffer, work bytes and list by default; IDENTIFY says where a station's are): the panel refuses every write to it; set \"writable\": false, "
            + "move the tag, or move the handler (the station's \"handlerVFirst\", which generate uses, then regenerate)"));
    }

    [Fact]
    public void Problems_HandlerTheProjectMoved_FlagsTheTagOnItsBytesAndNotTheTopOfV()
    {
        var tree = SampleProject.Tree();
        tree.Station()["handlerVFirst"] = 1000;
        var tags = tree.Station()["tags"]!.AsArray();
        tags.Add(new System.Text.Json.Nodes.JsonObject { ["symbol"] = "Top", ["address"] = "VW8000", ["writable"] = true });
        tags.Add(new System.Text.Json.Nodes.JsonObject { ["symbol"] = "Moved", ["address"] = "VW1604", ["writable"] = true });

        ProjectChecks.Problems(ProjectFile.Parse(tree.ToJsonString()).Project!).Should().ContainSingle().Which.Should().Be(new ProjectFileError(
            $"$.stations[0].tags[{tags.Count - 1}]",
            "tag Moved (VW1604) is writable, but VW1604 is in the handler's own V bytes VB1000-VB1605 (where the project's \"handlerVFirst\" puts "
            + "the full handler's buffer, work bytes and list; IDENTIFY says where a station's are): the panel refuses every write to it; "
            + "set \"writable\": false, move the tag, or move the handler (the station's \"handlerVFirst\", which generate uses, then regenerate)"));
    }

    [Fact]
    public void Problems_WritableTagOverlappingAReadOnlyTag_NamesBothTagsAndTheSharedByte()
    {
        var tree = SampleProject.Tree();
        var tags = tree.Station()["tags"]!.AsArray();
        tags.Add(new System.Text.Json.Nodes.JsonObject { ["symbol"] = "LevelLow", ["address"] = "VB151", ["writable"] = true });
        var loaded = ProjectFile.Parse(tree.ToJsonString());

        ProjectChecks.Problems(loaded.Project!).Should().Equal(new ProjectFileError(
            $"$.stations[0].tags[{tags.Count - 1}]",
            "tag LevelLow (VB151) is writable, but its byte VB151 is also in tag TankLevel (VW150), which the project marks read-only: "
            + "the panel refuses every write to it; set \"writable\": false on one of them, or move one"));
    }

    [Fact]
    public void Problems_CompactStopAndATagProblem_ListedInTheFilesOrder()
    {
        var tree = SampleProject.Tree();
        tree.Station()["compact"] = true;
        tree.Station()["tags"]!.AsArray().Add(new System.Text.Json.Nodes.JsonObject { ["symbol"] = "Spare", ["address"] = "VB8100", ["writable"] = true });

        ProjectChecks.Problems(ProjectFile.Parse(tree.ToJsonString()).Project!).Select(p => p.Location).Should().Equal(
            "$.stations[0]", $"$.stations[0].tags[{tree.Station()["tags"]!.AsArray().Count - 1}]");
    }
}
