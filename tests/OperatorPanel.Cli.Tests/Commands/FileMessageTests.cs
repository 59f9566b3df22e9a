using OperatorPanel.TestKit;

namespace OperatorPanel.Cli.Tests.Commands;

/// <summary>
/// Bad files and paths as a technician meets them on the command line: each message names the file and says what is
/// wrong in our words; the hint for a silent station names the notes file generate really writes.
/// </summary>
[Collection(RealTimeSerialCollection.Name)]
public sealed class FileMessageTests : IDisposable
{
    private readonly string _folder = Path.Combine(Path.GetTempPath(), "opanel-file-messages-" + Guid.NewGuid().ToString("N"));

    public FileMessageTests() => Directory.CreateDirectory(_folder);

    public void Dispose() => Directory.Delete(_folder, recursive: true);

    [Theory]
    [InlineData("project", "check")]
    [InlineData("watch")]
    public void ProjectVerbs_FolderEmptyOrTrailingComma_SayWhatIsWrongWithTheFile(params string[] verb)
    {
        var folder = Path.Combine(_folder, "folder.opproj");
        Directory.CreateDirectory(folder);
        var empty = Path.Combine(_folder, "empty.opproj");
        File.WriteAllBytes(empty, []);
        var comma = Path.Combine(_folder, "comma.opproj");
        File.WriteAllText(comma, "{\"schemaVersion\":1,\"name\":\"x\",}");

        Printed([.. verb, folder]).Should().Contain($"{folder}: file: cannot read it: it is a folder, not a file");
        Printed([.. verb, empty]).Should().Contain($"{empty}: file: the file is empty (0 bytes); a project file is JSON text starting with '{{'");
        Printed([.. verb, comma]).Should().Contain($"{comma}: line 1, column 31: not valid JSON: a comma before '}}' has nothing after it; remove that comma");
    }

    /// <summary>project check lists problems on stdout (its answer), the other verbs on stderr.</summary>
    private static string Printed(string[] args)
    {
        var run = CliRunner.Run(args);
        run.ExitCode.Should().Be(1);
        return run.Out + run.Error;
    }

    [Fact]
    public void StlRun_Folder_SaysItIsAFolder()
    {
        var run = CliRunner.Run("stl", "run", _folder, "--cpu", "224");

        run.ExitCode.Should().Be(1);
        run.Error.Should().Be($"opanel: {_folder}: cannot read it: it is a folder, not a file{Environment.NewLine}");
    }

    [Fact]
    public async Task Read_NothingAnswersWithProject_HintNamesTheNotesFileGenerateWrites()
    {
        using var pair = await SocatPtyPair.StartAsync();
        var project = Path.Combine(_folder, "line.opproj");
        CliRunner.Run("project", "new", "--cpu", "224", "--port", pair.PathA, "-o", project).ExitCode.Should().Be(0);
        CliRunner.Run("generate", project, "-o", _folder).ExitCode.Should().Be(0);
        var notes = Directory.GetFiles(_folder, "*-README.txt").Should().ContainSingle().Subject;

        var run = CliRunner.Run("read", "VB0", "--project", project);

        run.ExitCode.Should().Be(2);
        run.Error.Should().Contain($"(the top of the {Path.GetFileName(notes)} that opanel generate wrote beside the handler)");
    }
}
