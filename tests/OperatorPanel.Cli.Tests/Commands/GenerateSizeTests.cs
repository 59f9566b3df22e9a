using System.Text.Json;

namespace OperatorPanel.Cli.Tests.Commands;

/// <summary>
/// <c>opanel generate</c>'s size figures: the estimate beside the CPU's program memory in --stats and --json, and the
/// warning (with or without --stats) when the upper estimate is more than half the CPU's program memory.
/// </summary>
public sealed class GenerateSizeTests : IDisposable
{
    private readonly string _folder = Path.Combine(Path.GetTempPath(), "opanel-generate-size-tests-" + Guid.NewGuid().ToString("N"));

    public GenerateSizeTests() => Directory.CreateDirectory(_folder);

    private string Out => Path.Combine(_folder, "out");

    [Fact]
    public void GenerateStats_Cpu224_PrintsInstructionsNetworksTheEstimateTheProgramMemoryAndTheModbusComparison()
    {
        var run = CliRunner.Run("generate", NewProject("224"), "--protocol", "2", "-o", Out, "--stats");

        run.ExitCode.Should().Be(0, run.Error);
        Lines(run.Out).SkipWhile(l => !l.StartsWith("instructions generated:", StringComparison.Ordinal)).Take(5).Should().Equal(
            "instructions generated: 1177 in 353 networks",
            "program size estimated: 4708-8239 bytes (4-7 bytes an instruction)",
            "                        Siemens publishes no byte size per S7-200 instruction, so this is an estimate; Micro/WIN's compile gives the real size",
            "program memory:         8192 bytes on the CPU 224 (with run mode edit; 12288 without)",
            "for comparison:         Siemens' Modbus RTU slave library takes 1857 bytes of program and a 779-byte V block (S7-200 System Manual, Modbus Protocol Library)");
        run.Out.Should().Contain("V bytes reserved:       VB7764-VB8191 (428 bytes)");
    }

    [Fact]
    public void Generate_FullV3HandlerOnACpu221_OffersTheCompactHandlerFirstInLinesOfAtMost400Characters()
    {
        var run = CliRunner.Run("generate", NewProject("221"), "--compact", "false", "-o", Out);

        run.ExitCode.Should().Be(0);
        var lines = run.Error.Split(Environment.NewLine, StringSplitOptions.RemoveEmptyEntries);
        lines.Should().HaveCount(3);
        lines[0].Should().StartWith("opanel: warning STL050 the handler may leave too little room on the CPU 221: its ");
        lines[2].Should().MatchRegex(@"^opanel: use the compact handler \(the wizard's ""Compact handler"", ""compact"": true in the project or --compact: IDENTIFY, READ, WRITE, WRITE BITS; 2\d\d instructions, estimated \d+-\d+ bytes\), use a CPU");
        lines.Should().OnlyContain(l => l.Length <= 400);
    }

    [Fact]
    public void Generate_Cpu221WithoutStats_WarnsThatTheHandlerDoesNotFitAndStillWritesIt()
    {
        var run = CliRunner.Run("generate", NewProject("221"), "--protocol", "2", "-o", Out);

        run.ExitCode.Should().Be(0, "the size is a warning, not a refusal");
        run.Error.Should().Be(
            "opanel: warning STL050 the handler does not fit the CPU 221: its 1177 instructions take an estimated 4708-8239 bytes, "
            + "more than the CPU's 4096 bytes of program memory (with run mode edit) even at the lower figure." + Environment.NewLine
            + "opanel: Compile it with your program in Micro/WIN to see the real size; where they do not fit together:" + Environment.NewLine
            + "opanel: use a CPU with more program memory (CPU 224 8192 bytes, CPU 224XP 12288 bytes, CPU 226 16384 bytes), or reach this PLC over PPI "
            + "(\"protocol\": \"ppi\" in the project), which needs no program in the PLC." + Environment.NewLine);
        run.Out.Should().NotContain("STL050");
        File.ReadAllText(Path.Combine(Out, "PLC_2-README.txt")).Should()
            .Contain("  Estimated    4708-8239 bytes (4-7 bytes an instruction); Siemens publishes no byte size per")
            .And.Contain("  CPU          program memory 4096 bytes on the CPU 221\r\n")
            .And.Contain("  WARNING      the handler does not fit the CPU 221: its 1177 instructions take an estimated");
    }

    [Fact]
    public void GenerateJson_Cpu221_CarriesTheFiguresAndTheWarning()
    {
        var run = CliRunner.Run("generate", NewProject("221"), "--protocol", "2", "-o", Out, "--stats", "--json");

        run.ExitCode.Should().Be(0, run.Error);
        run.Error.Should().BeEmpty("with --json the warning is in the output");
        using var json = JsonDocument.Parse(run.Out);
        var stats = json.RootElement.GetProperty("stats");
        (stats.GetProperty("instructions").GetInt32(), stats.GetProperty("networks").GetInt32()).Should().Be((1177, 353));
        (stats.GetProperty("programBytesLow").GetInt32(), stats.GetProperty("programBytesHigh").GetInt32()).Should().Be((4708, 8239));
        (stats.GetProperty("bytesPerInstructionLow").GetInt32(), stats.GetProperty("bytesPerInstructionHigh").GetInt32()).Should().Be((4, 7));
        (stats.GetProperty("cpuProgramBytes").GetInt32(), stats.GetProperty("cpuProgramBytesWithoutRunModeEdit").GetInt32()).Should().Be((4096, 4096));
        stats.GetProperty("exceedsHalfOfProgramMemory").GetBoolean().Should().BeTrue();
        (stats.GetProperty("modbusSlaveProgramBytes").GetInt32(), stats.GetProperty("modbusSlaveVBytes").GetInt32()).Should().Be((1857, 779));
        stats.GetProperty("vBytes").GetInt32().Should().Be(428);
        var warning = json.RootElement.GetProperty("warnings").EnumerateArray().Should().ContainSingle().Subject;
        warning.GetProperty("id").GetString().Should().Be("STL050");
        warning.GetProperty("severity").GetString().Should().Be("warning");
        warning.GetProperty("message").GetString().Should().StartWith("the handler does not fit the CPU 221");
    }

    [Fact]
    public void Generate_Cpu226_WarnsTheUpperFigureIsOverHalfAndOffersPpiOnly()
    {
        var run = CliRunner.Run("generate", NewProject("226"), "--protocol", "2", "-o", Out);

        run.ExitCode.Should().Be(0);
        run.Error.Should().StartWith("opanel: warning STL050 the handler may leave too little room on the CPU 226: its 1177 instructions take "
            + "an estimated 4708-8239 bytes, and the upper figure is more than half of the CPU's 16384 bytes of program memory (with run mode edit).")
            .And.NotContain("more program memory");
    }

    [Theory]
    [InlineData("221", new string[0], "compact")]
    [InlineData("222", new string[0], "compact")]
    [InlineData("221", new[] { "--compact", "false" }, "full")]
    [InlineData("224", new string[0], "full")]
    [InlineData("224", new[] { "--compact" }, "compact")]
    public void GenerateStats_NewProject_GivesTheHandlerItsCpuIsOfferedUnlessCompactSaysOtherwise(string cpu, string[] options, string shape)
    {
        var run = CliRunner.Run(["generate", NewProject(cpu), "-o", Out, "--stats", .. options]);

        run.ExitCode.Should().Be(0, run.Error);
        run.Out.Should().Contain(shape == "compact" ? "list:                   none (compact handler: READ only)" : "list:                   up to 128 data bytes");
    }

    [Fact]
    public void Generate_Protocol2ForACompactProject_WritesTheOnlyShapeProtocol2Has()
    {
        var run = CliRunner.Run("generate", NewProject("221"), "--protocol", "2", "-o", Out, "--stats");

        run.ExitCode.Should().Be(0, run.Error);
        run.Out.Should().Contain("instructions generated: 1177");
    }

    public void Dispose() => Directory.Delete(_folder, recursive: true);

    private static string[] Lines(string text) => text.Split(Environment.NewLine);

    private string NewProject(string cpu)
    {
        var file = Path.Combine(_folder, $"{cpu}.opproj");
        CliRunner.Run("project", "new", "--cpu", cpu, "--station", "2", "--port", "COM1", "-o", file).ExitCode.Should().Be(0);
        return file;
    }
}
