using System.Text.Json;
using OperatorPanel.Cli;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Projects;

namespace OperatorPanel.Cli.Tests;

/// <summary>Runs <c>opanel project ...</c> in-process against files in a temporary folder.</summary>
public sealed class ProjectCommandTests : IDisposable
{
    private readonly string _folder = Path.Combine(Path.GetTempPath(), "opanel-cli-tests-" + Guid.NewGuid().ToString("N"));

    public ProjectCommandTests() => Directory.CreateDirectory(_folder);

    public static TheoryData<string, string> Cpus()
    {
        var data = new TheoryData<string, string>();
        foreach (var profile in CpuProfiles.All)
        {
            data.Add(CpuModelNames.ShortName(profile.Model), profile.Revision.ToString());
        }

        return data;
    }

    [Theory]
    [MemberData(nameof(Cpus))]
    public void New_EveryCpu_WritesAFileThatCheckAccepts(string cpu, string revision)
    {
        var file = FileIn($"{cpu}-{revision}.opproj");

        Run("project", "new", "--cpu", cpu, "--revision", revision, "-o", file).Code.Should().Be(0);
        var check = Run("project", "check", file);

        check.Code.Should().Be(0, check.Out);
        check.Out.Should().StartWith($"{file}: ok");
    }

    [Fact]
    public void New_IntoAFolderThatDoesNotExist_CreatesIt()
    {
        var file = Path.Combine(_folder, "plant", "line3", "line.opproj");

        var run = Run("project", "new", "--cpu", "224", "-o", file);

        run.Code.Should().Be(0, run.Error);
        Run("project", "check", file).Code.Should().Be(0);
        Directory.GetFiles(Path.GetDirectoryName(file)!).Select(Path.GetFileName).Should().Equal("line.opproj");
    }

    [Fact]
    public void New_Options_AreWrittenIntoTheProject()
    {
        var file = FileIn("line.opproj");

        var run = Run("project", "new", "--cpu", "226", "--station", "7", "--port", "/dev/ttyUSB0", "--name", "Palletiser", "-o", file);

        run.Code.Should().Be(0);
        run.Out.Should().Contain("project   \"Palletiser\", 1 station").And.Contain("station   7 \"PLC 7\": CPU 226 on /dev/ttyUSB0 9600 8N1 cable, full handler; 24 inputs, 16 outputs");
    }

    [Theory]
    [InlineData("221", true)]
    [InlineData("222", true)]
    [InlineData("224", false)]
    [InlineData("226", false)]
    public void New_Cpu221And222_StartWithTheCompactHandler(string cpu, bool compact)
    {
        var file = FileIn("line.opproj");

        var run = Run("project", "new", "--cpu", cpu, "-o", file);

        run.Code.Should().Be(0, run.Error);
        run.Out.Should().Contain(compact ? "cable, compact handler;" : "cable, full handler;");
        ProjectFile.Load(file).Project!.Stations[0].Compact.Should().Be(compact);
    }

    [Fact]
    public void New_ExistingFile_IsRefusedWithoutForce()
    {
        var file = FileIn("line.opproj");
        File.WriteAllText(file, "keep me");

        var run = Run("project", "new", "--cpu", "224", "-o", file);

        run.Code.Should().Be(1);
        run.Error.Should().Contain("already exists; add --force");
        File.ReadAllText(file).Should().Be("keep me");
    }

    [Fact]
    public void New_ExistingFileWithForce_ReplacesItAndKeepsBak()
    {
        var file = FileIn("line.opproj");
        File.WriteAllText(file, "old");

        Run("project", "new", "--cpu", "224", "-o", file, "--force").Code.Should().Be(0);

        File.ReadAllText(file + ".bak").Should().Be("old");
        Run("project", "check", file).Code.Should().Be(0);
    }

    [Theory]
    [InlineData("--cpu 225")]
    [InlineData("--cpu 224 --station 127")]
    [InlineData("--cpu 226 --revision early")]
    public void New_BadOption_ExitsOneAndWritesNothing(string options)
    {
        var file = FileIn("line.opproj");
        Run(["project", "new", "-o", file, .. options.Split(' ')]).Code.Should().Be(1);
        File.Exists(file).Should().BeFalse();
    }

    [Fact]
    public void New_BlankPort_ExitsOneSayingSo()
    {
        var run = Run("project", "new", "--cpu", "224", "--port", " ", "-o", FileIn("line.opproj"));

        run.Code.Should().Be(1);
        run.Error.Should().Contain("the serial port name is empty");
    }

    [Fact]
    public void New_Json_PrintsOkAndTheSummary()
    {
        var file = FileIn("line.opproj");

        var run = Run("project", "new", "--cpu", "222", "-o", file, "--json");

        using var json = JsonDocument.Parse(run.Out);
        json.RootElement.GetProperty("ok").GetBoolean().Should().BeTrue();
        json.RootElement.GetProperty("project").GetProperty("stations")[0].GetProperty("inputs").GetInt32().Should().Be(8);
    }

    [Fact]
    public void Check_BadFile_PrintsEveryProblemWithItsLocationAndExitsOne()
    {
        var file = FileIn("bad.opproj");
        File.WriteAllText(file, BadSample());

        var run = Run("project", "check", file);

        run.Code.Should().Be(1);
        run.Out.Split('\n', StringSplitOptions.RemoveEmptyEntries).Should().Equal(
            $"{file}: $.stations[0].link.stopBits: 2 stop bits: S7-200 Freeport always sends one stop bit; use 1",
            $"{file}: $.stations[0].tags[3].address: VW8191 ends at VB8192, past the last V byte VB8191 of CPU 224",
            $"{file}: 2 problems");
    }

    [Theory]
    [InlineData("generate", "nothing generated")]
    [InlineData("watch", "nothing watched")]
    [InlineData("read", "nothing sent")]
    [InlineData("write", "nothing sent")]
    [InlineData("identify", "nothing sent")]
    [InlineData("stop", "nothing sent")]
    public void VerbNeedingAProject_BadFile_ListsEveryProblemLikeCheckOneALine(string verb, string notDone)
    {
        var file = FileIn("bad.opproj");
        File.WriteAllText(file, BadSample());
        string[] args = verb switch
        {
            "generate" => ["generate", file, "-o", FileIn("plc"), "--station", "2"],
            "watch" => ["watch", file, "--once"],
            "read" => ["read", "VB0", "--project", file, "--demo"],
            "write" => ["write", "VB0=1", "--project", file, "--demo"],
            "identify" => ["identify", "--project", file, "--demo"],
            _ => ["stop", "--project", file, "--demo", "--yes"],
        };

        var run = Run(args);

        run.Code.Should().Be(1);
        run.Out.Should().BeEmpty();
        run.Error.Split(Environment.NewLine, StringSplitOptions.RemoveEmptyEntries).Should().Equal(
            $"{file}: $.stations[0].link.stopBits: 2 stop bits: S7-200 Freeport always sends one stop bit; use 1",
            $"{file}: $.stations[0].tags[3].address: VW8191 ends at VB8192, past the last V byte VB8191 of CPU 224",
            $"opanel: {file}: 2 problems; {notDone}");
    }

    [Fact]
    public void Check_FileBeyondTheProblemLimit_CountsMoreThanAHundredNotTheLinesListed()
    {
        var file = FileIn("many.opproj");
        File.WriteAllText(file, ManyBrokenStations());

        var run = Run("project", "check", file);

        run.Code.Should().Be(1);
        var lines = run.Out.Split('\n', StringSplitOptions.RemoveEmptyEntries);
        lines.Should().HaveCount(102);
        lines[^2].Should().Be($"{file}: file: more than 100 problems; the rest are not listed: correct these and load the file again");
        lines[^1].Should().Be($"{file}: more than 100 problems");
    }

    [Fact]
    public void VerbNeedingAProject_FileBeyondTheProblemLimit_CountsMoreThanAHundred()
    {
        var file = FileIn("many.opproj");
        File.WriteAllText(file, ManyBrokenStations());

        var run = Run("generate", file, "-o", FileIn("plc"));

        run.Code.Should().Be(1);
        run.Error.Split(Environment.NewLine, StringSplitOptions.RemoveEmptyEntries)[^1].Should().Be($"opanel: {file}: more than 100 problems; nothing generated");
    }

    [Fact]
    public void LinkVerb_BadProjectFileJson_GivesTheFileAndItsProblemsLikeGenerate()
    {
        var file = FileIn("bad.opproj");
        File.WriteAllText(file, BadSample());

        var run = Run("read", "VB0", "--project", file, "--demo", "--json");

        run.Code.Should().Be(1);
        using var json = JsonDocument.Parse(run.Out);
        json.RootElement.GetProperty("file").GetString().Should().Be(file);
        json.RootElement.GetProperty("problems").GetArrayLength().Should().Be(2);
        json.RootElement.GetProperty("error").GetString().Should().Be($"{file}: 2 problems; nothing sent");
    }

    [Fact]
    public void Check_OneAlarmOneTag_SummaryCountsInTheSingular()
    {
        var file = FileIn("line.opproj");
        Run("project", "new", "--cpu", "221", "-o", file).Code.Should().Be(0);
        var json = System.Text.Json.Nodes.JsonNode.Parse(File.ReadAllText(file))!;
        json["stations"]![0]!["tags"] = System.Text.Json.Nodes.JsonNode.Parse("""[{"symbol":"Count","address":"VW0"}]""");
        json["stations"]![0]!["alarms"] = System.Text.Json.Nodes.JsonNode.Parse("""[{"flag":"M0.0","text":"Jam"}]""");
        File.WriteAllText(file, json.ToJsonString());

        var run = Run("project", "check", file);

        run.Code.Should().Be(0, run.Out);
        run.Out.Should().Contain("; 6 inputs, 4 outputs, 1 tag, 1 alarm\n");
    }

    [Fact]
    public void Check_BadFileJson_ListsProblems()
    {
        var file = FileIn("bad.opproj");
        File.WriteAllText(file, BadSample());

        var run = Run("project", "check", file, "--json");

        run.Code.Should().Be(1);
        using var json = JsonDocument.Parse(run.Out);
        json.RootElement.GetProperty("ok").GetBoolean().Should().BeFalse();
        var problems = json.RootElement.GetProperty("problems");
        problems.GetArrayLength().Should().Be(2);
        problems[1].GetProperty("location").GetString().Should().Be("$.stations[0].tags[3].address");
    }

    [Fact]
    public void Check_Sample_SummarisesTheLine()
    {
        var run = Run("project", "check", SamplePath(), "--json");

        run.Code.Should().Be(0);
        using var json = JsonDocument.Parse(run.Out);
        json.RootElement.GetProperty("ok").GetBoolean().Should().BeTrue();
        json.RootElement.GetProperty("problems").GetArrayLength().Should().Be(0);
        var station = json.RootElement.GetProperty("project").GetProperty("stations")[0];
        station.GetProperty("name").GetString().Should().Be("Filler");
        station.GetProperty("alarms").GetInt32().Should().Be(8);
    }

    [Fact]
    public void Check_MissingFile_ExitsOneNamingTheFile()
    {
        var file = FileIn("missing.opproj");

        var run = Run("project", "check", file);

        run.Code.Should().Be(1);
        run.Out.Should().StartWith($"{file}: file: cannot read it: there is no such file");
    }

    public void Dispose() => Directory.Delete(_folder, recursive: true);

    internal static string SamplePath()
    {
        for (var folder = new DirectoryInfo(AppContext.BaseDirectory); folder is not null; folder = folder.Parent)
        {
            var candidate = Path.Combine(folder.FullName, "samples", "bottling-line.opproj");
            if (File.Exists(candidate))
            {
                return candidate;
            }
        }

        throw new FileNotFoundException("samples/bottling-line.opproj not found");
    }

    private static string BadSample() => File.ReadAllText(SamplePath())
        .Replace("\"VD120\"", "\"VW8191\"", StringComparison.Ordinal)
        .Replace("\"stopBits\": 1", "\"stopBits\": 2", StringComparison.Ordinal);

    private static string ManyBrokenStations() =>
        "{\"schemaVersion\":1,\"name\":\"x\",\"refresh\":{\"mode\":\"continuous\"},\"stations\":[" + string.Join(',', Enumerable.Repeat("{}", 300)) + "]}";

    private string FileIn(string name) => Path.Combine(_folder, name);

    private (int Code, string Out, string Error) Run(params string[] args)
    {
        using var output = new StringWriter();
        using var error = new StringWriter();
        var code = OpanelApp.Run([.. args, "--log-dir", Path.Combine(_folder, "logs")], output, error);
        return (code, output.ToString().Replace("\r\n", "\n", StringComparison.Ordinal), error.ToString());
    }
}
