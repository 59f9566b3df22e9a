using OperatorPanel.Core.Projects;

namespace OperatorPanel.Core.Tests.Projects;

/// <summary>
/// What a technician reads for a project that cannot be loaded: one sentence in our words saying what is wrong with the
/// file, never the runtime's ("Access to the path ... is denied", "when isFinalBlock is true", "Change the reader options").
/// </summary>
public sealed class ProjectFileMessageTests
{
    private static readonly string[] RuntimeWords =
        ["isFinalBlock", "reader options", "Access to the path", "Could not find", "JsonReaderOptions", "LineNumber", "BytePosition", "token"];

    [Fact]
    public void Load_Folder_SaysItIsAFolder()
    {
        using var folder = new TempFolder();
        var path = folder.File("line.opproj");
        Directory.CreateDirectory(path);

        ProjectFile.Load(path).Errors.Should().Equal(new ProjectFileError("file", "cannot read it: it is a folder, not a file"));
    }

    [Fact]
    public void Load_EmptyFile_SaysItIsEmpty()
    {
        using var folder = new TempFolder();
        var path = folder.File("line.opproj");
        File.WriteAllBytes(path, []);

        ProjectFile.Load(path).Errors.Should().Equal(new ProjectFileError("file", "the file is empty (0 bytes); a project file is JSON text starting with '{'"));
    }

    [Fact]
    public void Load_MissingFile_SaysThereIsNoSuchFile()
    {
        using var folder = new TempFolder();

        ProjectFile.Load(folder.File("nope.opproj")).Errors.Should().Equal(new ProjectFileError("file", "cannot read it: there is no such file"));
    }

    [Fact]
    public void Load_MissingFolder_NamesTheFolder()
    {
        using var folder = new TempFolder();
        var missing = folder.File("gone");

        ProjectFile.Load(Path.Combine(missing, "x.opproj")).Errors.Should().Equal(
            new ProjectFileError("file", $"cannot read it: the folder {missing} does not exist"));
    }

    [Fact]
    public void Parse_TrailingComma_SaysWhichCommaToRemove()
    {
        ProjectFile.Parse("{\"schemaVersion\":1,\"name\":\"x\",}").Errors.Should().Equal(
            new ProjectFileError("line 1, column 31", "not valid JSON: a comma before '}' has nothing after it; remove that comma"));
    }

    [Theory]
    [InlineData("", "line 1, column 1", "not valid JSON: there is no text; a project file is JSON text starting with '{'")]
    [InlineData("{\n  \"a\": 1\n", "line 3, column 1", "not valid JSON: the text ends too early: a closing '}' or ']' is missing (was the file cut short?)")]
    [InlineData("{ // note\n}", "line 1, column 3", "not valid JSON: comments (// or /* */) are not allowed in a project file")]
    [InlineData("{ 'name': 1 }", "line 1, column 3", "not valid JSON: names and text go in double quotes (\"), not single quotes")]
    [InlineData("{ \"a\": 1 \"b\": 2 }", "line 1, column 10", "not valid JSON: a comma is missing before this")]
    [InlineData("{ \"a\": True }", "line 1, column 8", "not valid JSON: 'True' is not a value: text goes in double quotes, and true, false and null in lower case")]
    [InlineData("{ name: 1 }", "line 1, column 3", "not valid JSON: 'name' is not a value: text goes in double quotes, and true, false and null in lower case")]
    [InlineData("[1, 2] x", "line 1, column 8", "not valid JSON: there is more text after the end of the JSON")]
    public void Parse_CommonMistakes_AreNamedInOurWords(string text, string location, string message)
    {
        ProjectFile.Parse(text).Errors.Should().Equal(new ProjectFileError(location, message));
    }

    [Theory]
    [InlineData("{")]
    [InlineData("{\"a\":}")]
    [InlineData("{\"a\":1,,}")]
    [InlineData("{\"a\":\"x\n\"}")]
    [InlineData("{\"a\":01}")]
    [InlineData("{\"a\":-}")]
    [InlineData("{\"a\":\"\\q\"}")]
    [InlineData("]")]
    [InlineData("{\"a\" 1}")]
    public void Parse_AnyBrokenJson_SpeaksNoRuntimeWords(string text)
    {
        var message = ProjectFile.Parse(text).Errors.Should().ContainSingle().Subject.Message;

        message.Should().StartWith("not valid JSON: ");
        foreach (var words in RuntimeWords)
        {
            message.Should().NotContainEquivalentOf(words);
        }
    }
}
