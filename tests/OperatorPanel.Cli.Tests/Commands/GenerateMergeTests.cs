using System.Text.Json;

namespace OperatorPanel.Cli.Tests.Commands;

/// <summary>Runs <c>opanel generate --merge</c> in-process on a project and a user program in a temporary folder.</summary>
public sealed class GenerateMergeTests : IDisposable
{
    private const string UserProgram =
        "ORGANIZATION_BLOCK MAIN:OB1\r\nBEGIN\r\nNetwork 1 // user\r\nLD     I0.0\r\n=      Q0.0\r\nEND_ORGANIZATION_BLOCK\r\n";

    private readonly string _folder = Path.Combine(Path.GetTempPath(), "opanel-merge-tests-" + Guid.NewGuid().ToString("N"));

    public GenerateMergeTests() => Directory.CreateDirectory(_folder);

    [Fact]
    public void GenerateMerge_NoCollision_WritesTheMergedFileBesideTheOthers()
    {
        var run = CliRunner.Run("generate", NewProject(), "-o", Out, "--merge", UserFile(UserProgram));

        run.ExitCode.Should().Be(0, run.Error);
        Directory.GetFiles(Out).Select(Path.GetFileName).Should().BeEquivalentTo(
            "PLC_2-handler.awl", "PLC_2-symbols.txt", "PLC_2-README.txt", "PLC_2-merged.awl");
        var merged = File.ReadAllText(Path.Combine(Out, "PLC_2-merged.awl"));
        merged.Should().StartWith("ORGANIZATION_BLOCK MAIN:OB1\r\nBEGIN\r\nNetwork 1 // Operator panel: call the port handler every scan\r\n")
            .And.Contain("LD     I0.0\r\n=      Q0.0\r\nEND_ORGANIZATION_BLOCK\r\nSUBROUTINE_BLOCK OP_PANEL:SBR63\r\n");
    }

    [Fact]
    public void GenerateMerge_Collision_PrintsFileLineAndIdAndWritesNothing()
    {
        var user = UserProgram.Replace("=      Q0.0", "MOVW   0, VW8000", StringComparison.Ordinal);

        var run = CliRunner.Run("generate", NewProject(), "-o", Out, "--merge", UserFile(user));

        run.ExitCode.Should().Be(2);
        run.Error.Should().Contain("user.awl:5: STL022 VW8000 (VB8000-VB8001) overlaps the handler's VB7586-VB8191; move the handler with --buffer VBn", "the protocol 3 handler's 606 V bytes at the top of V");
        Directory.Exists(Out).Should().BeFalse();
    }

    [Fact]
    public void GenerateMerge_CollisionResolvedByMovingTheBuffer_Writes()
    {
        var user = UserProgram.Replace("=      Q0.0", "MOVW   0, VW8000", StringComparison.Ordinal);

        var run = CliRunner.Run("generate", NewProject(), "-o", Out, "--merge", UserFile(user), "--buffer", "VB1000");

        run.ExitCode.Should().Be(0, run.Error);
        File.ReadAllText(Path.Combine(Out, "PLC_2-merged.awl")).Should().Contain("MOVW   0, VW8000\r\n").And.Contain("VB1000");
    }

    [Fact]
    public void GenerateMerge_Json_ReportsCollisionsWithLineAndId()
    {
        var user = UserProgram.Replace("=      Q0.0", "ATCH   MY_RX, 23", StringComparison.Ordinal);

        var run = CliRunner.Run("generate", NewProject(), "-o", Out, "--merge", UserFile(user), "--json");

        run.ExitCode.Should().Be(2);
        using var json = JsonDocument.Parse(run.Out);
        json.RootElement.GetProperty("ok").GetBoolean().Should().BeFalse();
        var first = json.RootElement.GetProperty("diagnostics")[0];
        (first.GetProperty("file").GetString(), first.GetProperty("line").GetInt32(), first.GetProperty("id").GetString(), first.GetProperty("severity").GetString())
            .Should().Be(("user.awl", 5, "STL020", "error"));
    }

    [Fact]
    public void GenerateMerge_Warning_PrintedAndStillWritten()
    {
        var user = UserProgram.Replace("=      Q0.0", "MOVB   1, *VD0", StringComparison.Ordinal);

        var run = CliRunner.Run("generate", NewProject(), "-o", Out, "--merge", UserFile(user));

        run.ExitCode.Should().Be(0, run.Error);
        run.Error.Should().Contain("user.awl:5: warning STL025 *VD0: an indirect access cannot be checked");
        File.Exists(Path.Combine(Out, "PLC_2-merged.awl")).Should().BeTrue();
    }

    [Fact]
    public void GenerateMerge_MissingUserFile_ExitsOne()
    {
        var run = CliRunner.Run("generate", NewProject(), "-o", Out, "--merge", Path.Combine(_folder, "none.awl"));

        run.ExitCode.Should().Be(1);
        run.Error.Should().Contain("cannot read");
    }

    [Fact]
    public void GenerateMerge_Ob1HeaderWithoutName_RefusedWithLineAndRule()
    {
        var user = UserProgram.Replace("ORGANIZATION_BLOCK MAIN:OB1", "ORGANIZATION_BLOCK OB1", StringComparison.Ordinal);

        var run = CliRunner.Run("generate", NewProject(), "-o", Out, "--merge", UserFile(user));

        run.ExitCode.Should().Be(2);
        run.Error.Should().Contain("user.awl:1: STL029 Micro/WIN refuses the user's program here (AWL012): the header of OB1 has no name")
            .And.Contain("opanel: nothing written: the merge with user.awl was refused (1 problem(s))");
        Directory.Exists(Out).Should().BeFalse();
    }

    [Fact]
    public void GenerateMerge_SymbolTable_SymbolOnTheHandlersBytesIsACollision()
    {
        var user = UserProgram.Replace("=      Q0.0", "MOVW   0, Recipe", StringComparison.Ordinal);
        var symbols = Path.Combine(_folder, "symbols.txt");
        File.WriteAllText(symbols, "Symbol\tAddress\tComment\r\nRecipe\tVW8000\trecipe number\r\n");

        var project = NewProject();
        var without = CliRunner.Run("generate", project, "-o", Out, "--merge", UserFile(user));
        without.ExitCode.Should().Be(0, without.Error);
        without.Error.Should().Contain("user.awl:5: warning STL027");
        Directory.Delete(Out, recursive: true);

        var run = CliRunner.Run("generate", project, "-o", Out, "--merge", UserFile(user), "--symbols", symbols);

        run.ExitCode.Should().Be(2);
        run.Error.Should().Contain("user.awl:5: STL022 VW8000");
    }

    [Fact]
    public void GenerateMerge_SymbolsWithoutMerge_ExitOne()
    {
        var run = CliRunner.Run("generate", NewProject(), "-o", Out, "--symbols", Path.Combine(_folder, "symbols.txt"));

        run.ExitCode.Should().Be(1);
        run.Error.Should().Contain("--symbols goes with --merge");
    }

    public void Dispose() => Directory.Delete(_folder, recursive: true);

    private string Out => Path.Combine(_folder, "out");

    private string UserFile(string text)
    {
        var path = Path.Combine(_folder, "user.awl");
        File.WriteAllText(path, text);
        return path;
    }

    private string NewProject()
    {
        var file = Path.Combine(_folder, "224-2.opproj");
        CliRunner.Run("project", "new", "--cpu", "224", "--station", "2", "--port", "COM1", "-o", file).ExitCode.Should().Be(0);
        return file;
    }
}
