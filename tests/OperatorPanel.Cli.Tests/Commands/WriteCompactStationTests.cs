namespace OperatorPanel.Cli.Tests.Commands;

/// <summary>
/// <c>opanel write --project</c> for a compact station: the handler's own V bytes are the compact handler's 74, and
/// <c>--demo</c> simulates that handler, so a byte only the full handler would keep is written.
/// </summary>
public sealed class WriteCompactStationTests : IDisposable
{
    private readonly string _folder = Directory.CreateTempSubdirectory("opanel-write-compact-").FullName;

    [Fact]
    public void Write_CompactStationsOwnVBytes_AreRefusedNamingTheCompactRange()
    {
        var project = CompactProject();

        var run = CliRunner.Run("write", "VB2000=9", "--project", project, "--demo");

        run.ExitCode.Should().Be(1);
        run.Out.Should().BeEmpty();
        run.Error.Should().Be("opanel: VB2000 is in the handler's own V bytes VB1870-VB2047 (where generate puts the compact handler's buffer and "
            + "work bytes by default; IDENTIFY says where a station's are); nothing written" + Environment.NewLine);
    }

    [Fact]
    public void Write_ByteOnlyTheFullHandlerKeeps_IsWrittenToTheCompactDemoStation()
    {
        // VB1500 lies in a CPU 221's full handler (VB1442-VB2047), not in the compact one the project names.
        var project = CompactProject();

        var run = CliRunner.Run("write", "VB1500=9", "--project", project, "--demo");

        run.ExitCode.Should().Be(0, run.Out + run.Error);
        run.Out.Should().Be("VB1500   0 -> 9  confirmed" + Environment.NewLine);
    }

    public void Dispose() => Directory.Delete(_folder, recursive: true);

    /// <summary>A CPU 221 project: <c>project new</c> gives it the compact handler.</summary>
    private string CompactProject()
    {
        var file = Path.Combine(_folder, "line.opproj");
        var created = CliRunner.Run("project", "new", "--cpu", "221", "-o", file);
        created.ExitCode.Should().Be(0, created.Error);
        return file;
    }
}
