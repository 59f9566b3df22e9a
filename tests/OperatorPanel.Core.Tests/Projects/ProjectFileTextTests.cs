using System.Text.Json.Nodes;
using OperatorPanel.Core.Projects;

namespace OperatorPanel.Core.Tests.Projects;

/// <summary>
/// Names and texts of a project (TextRule): at most their limit of characters, no control characters. A file that
/// breaks the rule does not load, and each offending item is named by its place and its text, control characters shown
/// as their codes.
/// </summary>
public sealed class ProjectFileTextTests
{
    private const string ControlHint = "which a screen does not show or takes as commands; remove them";

    public static TheoryData<string, string, string> EveryText() => new()
    {
        { "$.name", "the project name", "project" },
        { "$.stations[0].name", "the station name", "station" },
        { "$.stations[0].link.port", "the serial port name", "port" },
        { "$.stations[0].inputs[0].symbol", "the symbol", "input" },
        { "$.stations[0].outputs[0].description", "the description", "output description" },
        { "$.stations[0].tags[0].symbol", "the symbol", "tag" },
        { "$.stations[0].tags[0].description", "the description", "tag description" },
        { "$.stations[0].alarms[0].text", "the alarm text", "alarm" },
    };

    [Fact]
    public void Parse_StationNameOfThreeHundredCharacters_RefusedNamingTheLimitAndWhy()
    {
        BadFile.Expect(
            t => t.Station()["name"] = new string('F', 300),
            "$.stations[0].name",
            $"the station name '{new string('F', 40)}...' is 300 characters long; at most 64: generate names its files after it (NAME-handler.awl), "
                + "and their path must fit in Windows' 260 characters");
    }

    [Fact]
    public void Parse_NamesAndTextsAtTheirLimits_Load()
    {
        var tree = SampleProject.Tree();
        tree["name"] = new string('P', TextRule.ProjectName.MaxChars);
        tree.Station()["name"] = new string('S', TextRule.StationName.MaxChars);
        tree.Station()["tags"]![0]!["symbol"] = new string('T', TextRule.Symbol.MaxChars);
        tree.Station()["tags"]![0]!["description"] = new string('d', TextRule.Description.MaxChars);
        tree.Station()["alarms"]![0]!["text"] = new string('a', TextRule.AlarmText.MaxChars);

        var result = ProjectFile.Parse(tree.ToJsonString());

        result.Errors.Should().BeEmpty();
        (TextRule.StationName.MaxChars, TextRule.Symbol.MaxChars, TextRule.AlarmText.MaxChars, TextRule.Description.MaxChars).Should().Be((64, 64, 128, 256));
    }

    [Theory]
    [MemberData(nameof(EveryText))]
    public void Parse_EscapeInAnyNameOrText_RefusedAtThatItemWithTheCodeShown(string location, string noun, string text)
    {
        var problem = BadFile.SingleProblem(WithText(location, text + "\u001b[2J"));

        problem.Should().Be(new ProjectFileError(location, $"{noun} '{text}<16#1B>[2J' holds control characters (16#1B), {ControlHint}"));
    }

    [Theory]
    [MemberData(nameof(EveryText))]
    public void Parse_OneCharacterOverTheLimit_RefusedAtThatItem(string location, string noun, string text)
    {
        var limit = location.EndsWith("description", StringComparison.Ordinal) ? 256 : location.EndsWith("text", StringComparison.Ordinal) || location.EndsWith("port", StringComparison.Ordinal) ? 128 : 64;
        var tooLong = text + new string('x', limit + 1 - text.Length);

        var problem = BadFile.SingleProblem(WithText(location, tooLong));

        problem.Location.Should().Be(location);
        problem.Message.Should().StartWith($"{noun} '{tooLong[..40]}...' is {limit + 1} characters long; at most {limit}: ");
    }

    [Theory]
    [InlineData("\u0000", "16#00")]
    [InlineData("\t", "16#09")]
    [InlineData("\u007f", "16#7F")]
    [InlineData("\u009b", "16#9B")]
    public void Parse_NulTabDelOrC1InAStationName_Refused(string control, string code)
    {
        BadFile.Expect(
            t => t.Station()["name"] = "Filler" + control,
            "$.stations[0].name",
            $"the station name 'Filler<{code}>' holds control characters ({code}), {ControlHint}");
    }

    [Fact]
    public void Parse_SeveralBadTexts_EachNamedInOnePass()
    {
        var tree = SampleProject.Tree();
        tree.Station()["name"] = "Fil\u001bler";
        tree.Station()["tags"]![1]!["symbol"] = "Count\u0007";
        tree.Station()["alarms"]![2]!["text"] = new string('!', 129);

        var result = ProjectFile.Parse(tree.ToJsonString());

        result.Errors.Select(e => e.Location).Should().Equal("$.stations[0].name", "$.stations[0].tags[1].symbol", "$.stations[0].alarms[2].text");
    }

    [Fact]
    public void Parse_UnitWithABell_RefusedAsAControlCharacter()
    {
        BadFile.Expect(
            t => t.Station()["tags"]![0]!["unit"] = "bot\u0007",
            "$.stations[0].tags[0].unit",
            $"the unit 'bot<16#07>' holds control characters (16#07), {ControlHint}");
    }

    [Fact]
    public void Check_ProjectBuiltInCodeWithAnEscapeInAName_ReportsWhatTheFileWouldGet()
    {
        var project = ProjectFile.Parse(SampleProject.Text).Project!;
        var edited = project with { Stations = [project.Stations[0] with { Name = "Filler\u001b" }] };

        ProjectFile.Check(edited).Should().Equal(
            new ProjectFileError("$.stations[0].name", $"the station name 'Filler<16#1B>' holds control characters (16#1B), {ControlHint}"));
    }

    /// <summary>The sample with the string at <paramref name="location"/> (a path of the sample's first station) replaced.</summary>
    private static string WithText(string location, string text)
    {
        var tree = SampleProject.Tree();
        JsonNode node = tree;
        var steps = location[2..].Replace("]", string.Empty, StringComparison.Ordinal).Split('.', '[');
        for (var i = 0; i < steps.Length - 1; i++)
        {
            node = int.TryParse(steps[i], out var index) ? node[index]! : node[steps[i]]!;
        }

        node[steps[^1]] = text;
        return tree.ToJsonString();
    }
}
