namespace OperatorPanel.Cli.Tests.Commands;

/// <summary>
/// read and write with the project's symbols and its tags' units and ranges; every bad argument reported and nothing
/// sent; address and the link messages telling the truth about what the Freeport handler serves and writes.
/// </summary>
public sealed class TagArgumentTests
{
    private static readonly string Sample = SamplePath();

    [Fact]
    public void Read_SymbolsWithProject_ShowTheTagsScaledValueUnitAndSymbol()
    {
        var run = CliRunner.Run("read", "TankLevel", "BottleCount", "--project", Sample, "--demo");

        run.ExitCode.Should().Be(0, run.Error);
        var lines = run.Out.Split('\n', StringSplitOptions.RemoveEmptyEntries);
        lines[0].Should().MatchRegex(@"^VW150    \d+\.\d %\s+16#[0-9A-F]{4}\s+good  TankLevel$");
        lines[1].Should().MatchRegex(@"^VD100    \d+ bottles\s+16#[0-9A-F]{8}\s+good  BottleCount$");
    }

    [Fact]
    public void Read_SeveralBadArguments_ReportsEveryOneAndReadsNothing()
    {
        var run = CliRunner.Run("read", "BottleCoutn", "AIW0", "VB0", "VB99999", "--project", Sample, "--demo");

        run.ExitCode.Should().Be(1);
        run.Out.Should().BeEmpty();
        run.Error.Split('\n', StringSplitOptions.RemoveEmptyEntries).Should().Equal(
            "opanel: 'BottleCoutn': no tag, input or output of Filler has this symbol, and it is no address ('BottleCoutn': unknown memory area; an address starts with I, Q, M, V, SM, S, AIW, AQW, T or C)",
            "opanel: AIW0: the Freeport link reads only I, Q, M and V: its handler reaches memory through pointers, and an S7-200 pointer cannot reach analog values; copy the analog value to V in the PLC program (MOVW AIW0, VW100) and watch that, or read the station over PPI (\"protocol\": \"ppi\"), which reads analog values",
            "opanel: 'VB99999': byte number 99999 is larger than 65535",
            "opanel: 3 arguments are wrong; nothing read");
    }

    [Theory]
    [InlineData("RecipeNumber=9", "opanel: RecipeNumber (VB110): 9 is outside its range 1..8; nothing written")]
    [InlineData("VB110=99", "opanel: VB110=99: RecipeNumber (VB110) is 99 with that, outside its range 1..8; nothing written")]
    [InlineData("TankLevel=50", "opanel: VW150: the project marks TankLevel read-only; nothing written")]
    public void Write_OutsideTheTagsRangeHoweverNamed_RefusedAndNothingWritten(string assignment, string message)
    {
        var run = CliRunner.Run("write", assignment, "--project", Sample, "--demo");

        run.ExitCode.Should().Be(1);
        run.Error.Should().Be(message + Environment.NewLine);
        run.Out.Should().BeEmpty();
    }

    [Theory]
    [InlineData("VW150=5", "opanel: VW150 is part of tag TankLevel, which the project marks read-only; nothing written")]
    [InlineData("VB151=5", "opanel: VB151 is part of tag TankLevel (VW150), which the project marks read-only; nothing written")]
    [InlineData("V150.3=1", "opanel: V150.3 is part of tag TankLevel (VW150), which the project marks read-only; nothing written")]
    [InlineData("VD148=5", "opanel: VD148 overlaps tag TankLevel (VW150), which the project marks read-only; nothing written")]
    public void Write_AddressOfAReadOnlyTagsByte_RefusedNamingTheTagAndNothingWritten(string assignment, string message)
    {
        // TankLevel=50 is refused by its symbol; its address, or any of its bytes, is refused the same way.
        var run = CliRunner.Run("write", assignment, "--project", Sample, "--demo");

        run.ExitCode.Should().Be(1);
        run.Error.Should().Be(message + Environment.NewLine);
        run.Out.Should().BeEmpty();
    }

    [Fact]
    public void Write_ReadOnlyTagsBytesWithoutProject_AreAnyOtherBytes()
    {
        var run = CliRunner.Run("write", "VW150=5", "--demo");

        // Sent and judged by its read-back (the demo's tank may move it again at once: confirmed or mismatch).
        run.Error.Should().NotContain("read-only");
        run.Out.Should().MatchRegex(@"^VW150    \d+ -> 5  (confirmed|mismatch)");
    }

    [Fact]
    public void Write_SymbolInsideItsRange_WritesTheRawValueAndShowsItInTheTagsUnits()
    {
        var run = CliRunner.Run("write", "RecipeNumber=3", "FillTimeMs=1500", "--project", Sample, "--demo");

        run.ExitCode.Should().Be(0, run.Error);
        run.Out.Should().MatchRegex(@"VB110    \d+ -> 3  confirmed").And.MatchRegex(@"VW104    \d+ ms -> 1500 ms  confirmed");
    }

    [Fact]
    public void Write_SeveralBadAssignments_ReportsEveryOneAndWritesNothing()
    {
        var run = CliRunner.Run("write", "RecipeNumber=9", "VW200=1", "IB0=1", "Nope=1", "--project", Sample, "--demo");

        run.ExitCode.Should().Be(1);
        run.Out.Should().BeEmpty();
        var lines = run.Error.Split('\n', StringSplitOptions.RemoveEmptyEntries);
        lines.Should().HaveCount(4);
        lines[^1].Should().Be("opanel: 3 arguments are wrong; nothing written");
    }

    [Theory]
    [InlineData("SMB30", "224", "writable  no: SMB30: the Freeport handler does not serve SM")]
    [InlineData("SMB40", "224", "writable  no: SMB40: the Freeport handler does not serve SM")]
    [InlineData("VB9634", "226", "writable  no: VB9634 is in the handler's own V bytes VB9634-VB10239 (where generate puts the full handler's")]
    [InlineData("VW9633", "226", "writable  no: VW9633 is in the handler's own V bytes VB9634-VB10239")]
    [InlineData("VB9633", "226", "writable  yes")]
    [InlineData("VB100", "226", "writable  yes")]
    public void Address_BytesTheHandlerKeeps_AreNotWritable(string address, string cpu, string line)
    {
        var run = CliRunner.Run("address", address, "--cpu", cpu);

        run.ExitCode.Should().Be(0, run.Error);
        run.Out.Should().Contain(line);
    }

    [Fact]
    public void LinkMessages_ReadAndAddress_SayWhatEachLinkReads()
    {
        var read = CliRunner.Run("read", "AIW0", "--demo");
        var timer = CliRunner.Run("address", "T37", "--cpu", "224");
        var address = CliRunner.Run("address", "AIW0", "--cpu", "224");

        read.Error.Should().Contain("the Freeport link reads only I, Q, M and V");
        timer.Out.Should().Contain("link      not read by the Freeport link (it reads I, Q, M and V)")
            .And.Contain("ppi       read by the PPI link (it reads I, Q, M, V, SM, S, AIW, AQW, T and C); writable over PPI no: T37: the panel reads timer current values but never writes them");
        address.Out.Should().Contain("link      not read by the Freeport link (it reads I, Q, M and V)")
            .And.Contain("writable over PPI no: AIW0: analog inputs are read-only");
    }

    private static string SamplePath()
    {
        for (var folder = new DirectoryInfo(AppContext.BaseDirectory); folder is not null; folder = folder.Parent)
        {
            var candidate = Path.Combine(folder.FullName, "samples", "bottling-line.opproj");
            if (File.Exists(candidate))
            {
                return candidate;
            }
        }

        throw new InvalidOperationException("samples/bottling-line.opproj not found above the test folder");
    }
}
