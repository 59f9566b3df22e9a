using System.Text.Json.Nodes;
using OperatorPanel.Core.Projects;

namespace OperatorPanel.Core.Tests.Projects;

/// <summary>Assertions shared by the bad-file tests: the sample with one edit gives exactly one problem.</summary>
internal static class BadFile
{
    public static void Expect(Action<JsonObject> mutate, string location, string message)
    {
        var tree = SampleProject.Tree();
        mutate(tree);

        SingleProblem(tree.ToJsonString()).Should().Be(new ProjectFileError(location, message));
    }

    public static ProjectFileError SingleProblem(string text)
    {
        var result = ProjectFile.Parse(text);
        result.Ok.Should().BeFalse();
        return result.Errors.Should().ContainSingle().Subject;
    }
}
