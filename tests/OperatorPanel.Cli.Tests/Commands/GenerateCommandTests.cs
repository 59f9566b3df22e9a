using System.Text.Json;
using System.Text.Json.Nodes;

namespace OperatorPanel.Cli.Tests.Commands;

/// <summary>Runs <c>opanel generate</c> in-process on projects in a temporary folder.</summary>
public sealed class GenerateCommandTests : IDisposable
{
    private readonly string _folder = Path.Combine(Path.GetTempPath(), "opanel-generate-tests-" + Guid.NewGuid().ToString("N"));

    public GenerateCommandTests() => Directory.CreateDirectory(_folder);

    [Fact]
    public void Generate_OneStation_WritesTheThreeFiles()
    {
        var project = NewProject("224", "2");

        var run = CliRunner.Run("generate", project, "--protocol", "2", "-o", Out);

        run.ExitCode.Should().Be(0, run.Error);
        Directory.GetFiles(Out).Select(Path.GetFileName).Should().BeEquivalentTo("PLC_2-handler.awl", "PLC_2-symbols.txt", "PLC_2-README.txt");
        var awl = File.ReadAllBytes(Path.Combine(Out, "PLC_2-handler.awl"));
        awl.Should().NotContain(b => b > 0x7E);
        File.ReadAllText(Path.Combine(Out, "PLC_2-handler.awl")).Should().Contain("SUBROUTINE_BLOCK OP_PANEL:SBR63\r\n").And.Contain("LDB<>  VB8020, 2\r\n");
        File.ReadAllText(Path.Combine(Out, "PLC_2-symbols.txt")).Should().StartWith("OP_BUF\tVB7764\t");
    }

    [Fact]
    public void Generate_NoProtocolGiven_WritesTheProtocol3HandlerThePanelSpeaks()
    {
        var run = CliRunner.Run("generate", NewProject("224", "2"), "-o", Out);

        run.ExitCode.Should().Be(0, run.Error);
        File.ReadAllText(Path.Combine(Out, "PLC_2-symbols.txt")).Should().StartWith("OP_BUF\tVB7586\tPanel handler v3:", "V_FIRST of the full v3 handler on a CPU 224: 8192 - 606, even");
        File.ReadAllText(Path.Combine(Out, "PLC_2-handler.awl")).Should().Contain("SUBROUTINE_BLOCK OP_PANEL:SBR63\r\n");
    }

    [Theory]
    [InlineData(true, false)]
    [InlineData(false, true)]
    public void Generate_ProjectCompactOrCompactOption_WritesTheCompactHandler(bool inProject, bool option)
    {
        var project = NewProject("224", "2");
        var root = JsonNode.Parse(File.ReadAllText(project))!;
        root["stations"]![0]!["compact"] = inProject;
        File.WriteAllText(project, root.ToJsonString());

        var run = option ? CliRunner.Run("generate", project, "-o", Out, "--compact") : CliRunner.Run("generate", project, "-o", Out);

        run.ExitCode.Should().Be(0, run.Error);
        File.ReadAllText(Path.Combine(Out, "PLC_2-symbols.txt")).Should().StartWith("OP_BUF\tVB8014\t", "V_FIRST of the compact handler's 178 V bytes on a CPU 224: 8192 - 178");
    }

    [Theory]
    [InlineData(false, false)]
    [InlineData(true, true)]
    public void Generate_ProjectAllowStop_IncludesTheStopCodeOnlyWhenSet(bool allowStop, bool stopCode)
    {
        var project = NewProject("224", "2");
        var root = JsonNode.Parse(File.ReadAllText(project))!;
        root["stations"]![0]!["allowStop"] = allowStop;
        File.WriteAllText(project, root.ToJsonString());

        var run = CliRunner.Run("generate", project, "--protocol", "2", "-o", Out);

        run.ExitCode.Should().Be(0, run.Error);
        var awl = File.ReadAllText(Path.Combine(Out, "PLC_2-handler.awl"));
        awl.Contains("\r\nSTOP\r\n", StringComparison.Ordinal).Should().Be(stopCode, "the STOP instruction is in the handler only when the project allows it");
        awl.Contains("command 07 STOP", StringComparison.Ordinal).Should().Be(stopCode);
    }

    [Fact]
    public void Generate_ProjectCompactWithAllowStop_RefusedAsImpossibleInCheckWordsAndNothingWritten()
    {
        var project = NewProject("224", "2");
        var root = JsonNode.Parse(File.ReadAllText(project))!;
        (root["stations"]![0]!["name"], root["stations"]![0]!["compact"], root["stations"]![0]!["allowStop"]) = ("Filler", true, true);
        File.WriteAllText(project, root.ToJsonString());

        var run = CliRunner.Run("generate", project, "-o", Out);
        var check = CliRunner.Run("project", "check", project);

        run.ExitCode.Should().Be(2, "impossible handler settings, as every STLnnn");
        run.Error.Split(Environment.NewLine, StringSplitOptions.RemoveEmptyEntries).Should().Equal(
            "opanel: STL031: " + CompactWithStop,
            "opanel: nothing written: the handler settings above are impossible");
        Directory.Exists(Out).Should().BeFalse();
        check.Out.Should().Contain($"{project}: $.stations[0]: {CompactWithStop}\n", "project check says it in the same words");
    }

    [Theory]
    [InlineData(false, new[] { "--compact", "--allow-stop" }, "has --compact and --allow-stop, but", "leave out --compact for the full handler with STOP, or leave out --allow-stop for")]
    [InlineData(true, new[] { "--allow-stop" }, "has \"compact\": true and --allow-stop, but", "give --compact false (or set \"compact\": false) for the full handler with STOP, or leave out --allow-stop for")]
    [InlineData(false, new[] { "--compact", "--allow-stop", "--stats" }, "has --compact and --allow-stop, but", "leave out --compact for")]
    public void Generate_CompactAndAllowStopFromTheCommandLine_RefusedNamingWhereEachCameFrom(bool projectCompact, string[] options, string settings, string waysOut)
    {
        var project = NewProject("224", "2");
        var root = JsonNode.Parse(File.ReadAllText(project))!;
        root["stations"]![0]!["compact"] = projectCompact;
        File.WriteAllText(project, root.ToJsonString());

        var run = CliRunner.Run(["generate", project, "-o", Out, .. options]);

        run.ExitCode.Should().Be(2);
        run.Error.Should().StartWith($"opanel: STL031: PLC 2 (station 2) {settings} a compact handler has no STOP").And.Contain(waysOut);
        Directory.Exists(Out).Should().BeFalse();
    }

    [Fact]
    public void Generate_CompactWithAllowStopFalse_LeavesTheProjectsStopOut()
    {
        // The project allows STOP; --compact false gives the full handler, --allow-stop false the compact one without STOP.
        var project = NewProject("224", "2");
        var root = JsonNode.Parse(File.ReadAllText(project))!;
        root["stations"]![0]!["allowStop"] = true;
        File.WriteAllText(project, root.ToJsonString());

        var refused = CliRunner.Run("generate", project, "-o", Out, "--compact");
        var run = CliRunner.Run("generate", project, "-o", Out, "--compact", "--allow-stop", "false", "--stats");

        refused.ExitCode.Should().Be(2);
        refused.Error.Should().Contain("has --compact and \"allowStop\": true, but").And.Contain("give --allow-stop false (or set \"allowStop\": false)");
        run.ExitCode.Should().Be(0, run.Error);
        run.Out.Should().Contain("STOP command:           not included");
    }

    [Fact]
    public void Generate_Stats_PrintsTheHandlersFigures()
    {
        var project = NewProject("224", "2");

        var run = CliRunner.Run("generate", project, "--protocol", "2", "-o", Out, "--stats");

        run.ExitCode.Should().Be(0);
        run.Out.Should().Contain("V bytes reserved:       VB7764-VB8191 (428 bytes)")
            .And.Contain("READ CHANGES copies:    VB8072-VB8191 (120 bytes; READ CHANGES and STOP work bytes: 13)")
            .And.Contain("STOP command:           not included (07 gets error 05)")
            .And.Contain("instructions generated: 1177")
            .And.Contain("interrupt events used:  23, 10, 9")
            .And.Contain("blocks used:            OP_PANEL (SBR63), OP_RX (INT125), OP_DELAY (INT126), OP_TX (INT127)");
    }

    [Fact]
    public void Generate_Stats_PrintsEachWorstCaseRequestsInterruptScanAndScansPerReply()
    {
        var project = NewProject("224", "2");

        var run = CliRunner.Run("generate", project, "--protocol", "2", "-o", Out, "--stats");

        run.ExitCode.Should().Be(0, run.Error);
        run.Out.Should().Contain("  no request (a scan)                                      0 ->   0            43     0.000               0.000          0.121      0")
            .And.Contain("  IDENTIFY                                                12 ->  62          1519    46.408               0.429          9.503      7")
            .And.Contain("  READ LIST 20 items                                      14 -> 172          4633   145.755               0.429          9.072     21")
            .And.Contain("  READ CHANGES 77 bytes whole                             16 -> 174          4611   148.709               0.429          9.503     20")
            .And.Contain("  READ CHANGES none changed                               16 ->  20          3063    80.573               0.429          9.460     13")
            .And.Contain("  READ CHANGES 1 changed                                  16 ->  24          3205    84.272               0.429          9.018     14")
            .And.Contain("  READ CHANGES 40 changed                                 16 -> 174          6643   205.014               0.429          9.503     28")
            .And.Contain("  READ CHANGES list 1 of 2, none changed                  16 ->  20          3048    78.554               0.429          9.460     13")
            .And.Contain("  READ CHANGES list 2 of 2, none changed                  16 ->  20          2332    59.739               0.429          9.460     10")
            .And.Contain("  READ CHANGES OF LISTS 2 lists idle                      14 ->  22          4832   119.935               0.429          9.018     21")
            .And.Contain("  READ CHANGES OF LISTS 4 lists, no valid copy            14 ->  26          1383    36.980               0.429          9.018      8")
            .And.Contain("  READ CHANGES OF LISTS 4 lists, 9 changed in each        14 ->  62          6647   177.678               0.429          9.503     33")
            .And.Contain("worst interrupt routine: 0.499 ms (cut-off frame, then READ 20 items)")
            .And.Contain("worst added to one scan: 9.503 ms (IDENTIFY)")
            .And.Contain("most scans per reply:    51");
    }

    [Fact]
    public void Generate_StatsJson_ReportsTheMeasuredRequests()
    {
        var project = NewProject("224", "2");

        var run = CliRunner.Run("generate", project, "--protocol", "2", "-o", Out, "--stats", "--json");

        run.ExitCode.Should().Be(0, run.Error);
        using var json = JsonDocument.Parse(run.Out);
        var stats = json.RootElement.GetProperty("stats");
        var measured = stats.GetProperty("measured").EnumerateArray().ToList();
        measured.Should().HaveCount(22);
        measured[1].GetProperty("request").GetString().Should().Be("IDENTIFY");
        measured[1].GetProperty("replyChars").GetInt32().Should().Be(62);
        measured[1].GetProperty("instructions").GetInt64().Should().Be(1519);
        measured[1].GetProperty("microseconds").GetInt64().Should().Be(46408);
        measured[1].GetProperty("worstInterruptMicroseconds").GetInt64().Should().Be(429);
        measured[1].GetProperty("scans").GetInt32().Should().Be(7);
        stats.GetProperty("worstInstructions").GetInt64().Should().Be(12197);
        stats.GetProperty("worstMicroseconds").GetInt64().Should().Be(386260);
        stats.GetProperty("worstInterruptMicroseconds").GetInt64().Should().Be(498);
        stats.GetProperty("worstScanMicroseconds").GetInt64().Should().Be(9503);
        stats.GetProperty("mostScansPerReply").GetInt32().Should().Be(51);
        (stats.GetProperty("copyBytes").GetInt32(), stats.GetProperty("stopEnabled").GetBoolean()).Should().Be((120, false));
    }

    [Fact]
    public void Generate_Json_ReportsFilesAndStats()
    {
        var project = NewProject("226", "17");

        var run = CliRunner.Run("generate", project, "--protocol", "2", "-o", Out, "--plc-port", "1", "--buffer", "VB1000", "--stats", "--json");

        run.ExitCode.Should().Be(0);
        using var json = JsonDocument.Parse(run.Out);
        json.RootElement.GetProperty("ok").GetBoolean().Should().BeTrue();
        json.RootElement.GetProperty("files").GetArrayLength().Should().Be(3);
        var stats = json.RootElement.GetProperty("stats");
        stats.GetProperty("firstVByte").GetInt32().Should().Be(1000);
        stats.GetProperty("lastVByte").GetInt32().Should().Be(1427);
        stats.GetProperty("interruptEvents").EnumerateArray().Select(e => e.GetInt32()).Should().Equal(24, 10, 26);
    }

    [Theory]
    [InlineData("--plc-port", "1", "STL001")]
    [InlineData("--buffer", "VB8000", "STL005")]
    [InlineData("--reply-delay", "0", "STL007")]
    [InlineData("--writable", "I,Q", "STL011")]
    [InlineData("--sbr", "64", "STL009")]
    public void Generate_ImpossibleSetting_PrintsTheDiagnosticAndExits2(string option, string value, string id)
    {
        var project = NewProject("224", "2");

        var run = CliRunner.Run("generate", project, "--protocol", "2", "-o", Out, option, value);

        run.ExitCode.Should().Be(2);
        run.Error.Should().StartWith($"opanel: {id}: ");
        Directory.Exists(Out).Should().BeFalse();
    }

    [Fact]
    public void Generate_ImpossibleSettingWithJson_ListsTheDiagnostics()
    {
        var project = NewProject("224", "2");

        var run = CliRunner.Run("generate", project, "--protocol", "2", "-o", Out, "--plc-port", "1", "--json");

        run.ExitCode.Should().Be(2);
        using var json = JsonDocument.Parse(run.Out);
        json.RootElement.GetProperty("diagnostics")[0].GetProperty("id").GetString().Should().Be("STL001");
    }

    [Theory]
    [InlineData("--buffer", "MB10", "MB10")]
    [InlineData("--writable", "Q,X", "'X'")]
    public void Generate_UnreadableOption_IsBadInput(string option, string value, string named)
    {
        var run = CliRunner.Run("generate", NewProject("224", "2"), "-o", Out, option, value);

        run.ExitCode.Should().Be(1);
        run.Error.Should().Contain(named);
    }

    [Fact]
    public void Generate_OutputIsAFile_SaysSoAndWritesNothing()
    {
        var project = NewProject("224", "2");
        var file = Path.Combine(_folder, "plc");
        File.WriteAllText(file, "not a folder");

        var run = CliRunner.Run("generate", project, "--protocol", "2", "-o", file);

        run.ExitCode.Should().Be(1);
        run.Error.Should().Be($"opanel: {file} is a file, not a folder: give the folder for the generated files{Environment.NewLine}");
        File.ReadAllText(file).Should().Be("not a folder");
    }

    [Fact]
    public void Generate_AFileNameTakenByAFolder_WritesNothingAndSaysWhich()
    {
        var project = NewProject("224", "2");
        Directory.CreateDirectory(Path.Combine(Out, "PLC_2-README.txt"));
        File.WriteAllText(Path.Combine(Out, "PLC_2-handler.awl"), "the previous handler");

        var run = CliRunner.Run("generate", project, "-o", Out);

        run.ExitCode.Should().Be(1);
        run.Error.Should().Be($"opanel: {Path.Combine(Out, "PLC_2-README.txt")} is a folder, not a file: move or rename it; nothing was written{Environment.NewLine}");
        File.ReadAllText(Path.Combine(Out, "PLC_2-handler.awl")).Should().Be("the previous handler");
        File.Exists(Path.Combine(Out, "PLC_2-symbols.txt")).Should().BeFalse();
    }

    [Fact]
    public void Generate_SeveralStations_NeedsStation()
    {
        var project = TwoStationProject();

        var refused = CliRunner.Run("generate", project, "--protocol", "2", "-o", Out);
        var chosen = CliRunner.Run("generate", project, "--protocol", "2", "-o", Out, "--station", "9");

        refused.ExitCode.Should().Be(1);
        refused.Error.Should().Contain("choose one with --station");
        chosen.ExitCode.Should().Be(0, chosen.Error);
        File.Exists(Path.Combine(Out, "Capper-handler.awl")).Should().BeTrue();
    }

    public void Dispose() => Directory.Delete(_folder, recursive: true);

    private const string CompactWithStop = "Filler (station 2) has \"compact\": true and \"allowStop\": true, but a compact handler has no STOP: it would be generated "
        + "without the STOP that is allowed; set \"compact\": false for the full handler with STOP, or set \"allowStop\": false for the "
        + "compact handler without it";

    private string Out => Path.Combine(_folder, "out");

    private string NewProject(string cpu, string station)
    {
        var file = Path.Combine(_folder, $"{cpu}-{station}.opproj");
        CliRunner.Run("project", "new", "--cpu", cpu, "--station", station, "--port", "COM1", "-o", file).ExitCode.Should().Be(0);
        return file;
    }

    private string TwoStationProject()
    {
        var file = NewProject("224", "2");
        var root = JsonNode.Parse(File.ReadAllText(file))!;
        var stations = root["stations"]!.AsArray();
        var second = stations[0]!.DeepClone();
        second["name"] = "Capper";
        second["address"] = 9;
        stations.Add(second);
        File.WriteAllText(file, root.ToJsonString());
        return file;
    }
}
