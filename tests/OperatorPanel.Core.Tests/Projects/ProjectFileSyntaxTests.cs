using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Projects;

namespace OperatorPanel.Core.Tests.Projects;

/// <summary>Bad files of every structural kind: broken JSON, wrong types, unknown, missing and repeated properties, unreadable files. Each asserts the location and the message.</summary>
public sealed class ProjectFileSyntaxTests
{
    [Fact]
    public void Parse_MalformedJson_ReportsLineAndColumn()
    {
        var problem = BadFile.SingleProblem("{\n  \"schemaVersion\": 1,\n  \"name\": }\n");

        problem.Location.Should().Be("line 3, column 11");
        problem.Message.Should().StartWith("not valid JSON: ").And.NotContain("LineNumber");
    }

    [Fact]
    public void Parse_ColumnAfterNonAsciiText_CountsCharactersNotBytes()
    {
        BadFile.SingleProblem("{ \"name\": \"Łódź\" x").Location.Should().Be("line 1, column 18");
    }

    [Theory]
    [InlineData("")]
    [InlineData("   \n")]
    [InlineData("{")]
    [InlineData("[1, 2")]
    [InlineData("\"just a string")]
    public void Parse_EmptyOrTruncated_ReportsASyntaxProblem(string text)
    {
        BadFile.SingleProblem(text).Location.Should().StartWith("line ");
    }

    [Fact]
    public void Parse_RootNotAnObject_SaysWhatItFound()
    {
        BadFile.SingleProblem("[1]").Should().Be(new ProjectFileError("$", "expected an object, found an array"));
    }

    [Fact]
    public void Parse_SchemaVersionAsString_ReportsWrongType()
    {
        BadFile.Expect(t => t["schemaVersion"] = "1", "$.schemaVersion", "expected a whole number, found the string \"1\"");
    }

    [Fact]
    public void Parse_NewerSchemaVersion_ReportsOnlyThat()
    {
        var tree = SampleProject.Tree();
        tree["schemaVersion"] = 2;
        tree["futureThing"] = true;

        BadFile.SingleProblem(tree.ToJsonString()).Should().Be(new ProjectFileError(
            "$.schemaVersion", "schema version 2 is newer than this program reads (1); update Operator Panel"));
    }

    [Fact]
    public void Parse_HugeNumber_IsRefusedWithoutOverflow()
    {
        var text = SampleProject.Text.Replace("\"address\": 2,", "\"address\": 99999999999999999999999999,", StringComparison.Ordinal);

        BadFile.SingleProblem(text).Should().Be(new ProjectFileError("$.stations[0].address", "99999999999999999999999999 is far outside any allowed range"));
    }

    [Fact]
    public void Parse_UnknownProperty_ListsTheExpectedOnes()
    {
        BadFile.Expect(t => t["refresh"]!["minPeriod"] = 5, "$.refresh.minPeriod", "unknown property 'minPeriod'; expected mode, minimumPeriodMs");
    }

    [Fact]
    public void Parse_MissingRequiredProperty_IsReportedAtItsObject()
    {
        BadFile.Expect(t => t.Station().Remove("name"), "$.stations[0]", "missing required property 'name'");
    }

    [Fact]
    public void Parse_NullWhereABooleanBelongs_ReportsNull()
    {
        BadFile.Expect(t => t.Station()["tags"]![0]!["writable"] = null, "$.stations[0].tags[0].writable", "expected true or false, found null");
    }

    [Fact]
    public void Parse_DuplicatePropertyName_IsReported()
    {
        var text = SampleProject.Text.Replace("\"name\": \"Filler\",", "\"name\": \"Filler\", \"name\": \"Capper\",", StringComparison.Ordinal);

        BadFile.SingleProblem(text).Should().Be(new ProjectFileError("$.stations[0].name", "this property appears more than once"));
    }

    [Fact]
    public void Parse_LoneSurrogateEscape_IsAProblemNotAnException()
    {
        var text = SampleProject.Text.Replace("\"Start push button (NO)\"", "\"\\uD800\"", StringComparison.Ordinal);

        BadFile.SingleProblem(text).Should().Be(new ProjectFileError("$.stations[0].inputs[1].description", "the string is not valid Unicode text"));
    }

    [Fact]
    public void Parse_LoneSurrogateInAPropertyName_IsAProblemNotAnException()
    {
        ProjectFile.Parse("{\"\\uD800\": 1, \"schemaVersion\": 1}").Errors.Should().StartWith(
            new ProjectFileError("$", "a property name is not valid Unicode text"));
    }

    [Fact]
    public void Parse_SeveralProblems_ReportsEveryOneInFileOrder()
    {
        var tree = SampleProject.Tree();
        tree["refresh"]!["mode"] = 3;
        tree.Station()["cpu"]!["model"] = "999";
        tree.Station()["inputs"]![0]!["symbol"] = "";
        tree.Station()["alarms"]![7]!["class"] = "panic";

        ProjectFile.Parse(tree.ToJsonString()).Errors.Select(e => e.Location).Should().Equal(
            "$.refresh.mode", "$.stations[0].cpu.model", "$.stations[0].inputs[0].symbol", "$.stations[0].alarms[7].class");
    }

    [Fact]
    public void Load_BinaryGarbage_SaysItIsNotText()
    {
        using var folder = new TempFolder();
        var path = folder.File("garbage.opproj");
        File.WriteAllBytes(path, [0x7B, 0xFF, 0xFE, 0x00, 0x81]);

        ProjectFile.Load(path).Errors.Should().Equal(
            new ProjectFileError("file", "not UTF-8 text (invalid byte at offset 1); is this a project file?"));
    }

    [Fact]
    public void Parse_NestingDeeperThanTheReaderAllows_IsASyntaxProblem()
    {
        BadFile.SingleProblem(new string('[', 100_000)).Location.Should().StartWith("line 1, column ");
    }

    [Fact]
    public void Parse_MillionEmptyStations_ListsTheFirstHundredProblemsAndSaysThereAreMore()
    {
        var text = "{\"schemaVersion\":1,\"name\":\"x\",\"refresh\":{\"mode\":\"continuous\"},\"stations\":[" + string.Join(',', Enumerable.Repeat("{}", 1_000_000)) + "]}";

        var result = ProjectFile.Parse(text);

        result.Errors.Should().HaveCount(101);
        result.Errors[0].Should().Be(new ProjectFileError("$.stations[0]", "missing required property 'name'"));
        result.Errors[^1].Should().Be(new ProjectFileError("file", "more than 100 problems; the rest are not listed: correct these and load the file again"));
    }
}
