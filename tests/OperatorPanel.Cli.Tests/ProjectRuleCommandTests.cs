using System.Text.Json;

namespace OperatorPanel.Cli.Tests;

/// <summary>
/// <c>opanel project check</c> and <c>project new</c> on what the file's rules refuse beyond its syntax: a compact station
/// with STOP allowed, names and texts too long or holding control characters, and a save onto a read-only file.
/// </summary>
public sealed class ProjectRuleCommandTests : IDisposable
{
    private readonly string _folder = Path.Combine(Path.GetTempPath(), "opanel-cli-rule-tests-" + Guid.NewGuid().ToString("N"));

    public ProjectRuleCommandTests() => Directory.CreateDirectory(_folder);

    [Fact]
    public void Check_CompactStationWithAllowStop_ReportsTheStationBothPropertiesAndTheWaysOut()
    {
        var file = FileIn("line.opproj");
        File.WriteAllText(file, File.ReadAllText(ProjectCommandTests.SamplePath()).Replace("\"allowStop\": true,", "\"allowStop\": true, \"compact\": true,", StringComparison.Ordinal));

        var run = Run("project", "check", file);

        run.Code.Should().Be(1);
        run.Out.Split('\n', StringSplitOptions.RemoveEmptyEntries).Should().Equal(
            $"{file}: $.stations[0]: Filler (station 2) has \"compact\": true and \"allowStop\": true, but a compact handler has no STOP: "
                + "it would be generated without the STOP that is allowed; set \"compact\": false for the full handler with STOP, or set "
                + "\"allowStop\": false for the compact handler without it",
            $"{file}: 1 problem");
    }

    [Fact]
    public void Check_CompactStationWithAllowStopJson_NotOkWithTheProblem()
    {
        var file = FileIn("line.opproj");
        File.WriteAllText(file, File.ReadAllText(ProjectCommandTests.SamplePath()).Replace("\"allowStop\": true,", "\"allowStop\": true, \"compact\": true,", StringComparison.Ordinal));

        var run = Run("project", "check", file, "--json");

        run.Code.Should().Be(1);
        using var json = JsonDocument.Parse(run.Out);
        json.RootElement.GetProperty("ok").GetBoolean().Should().BeFalse();
        json.RootElement.GetProperty("problems")[0].GetProperty("location").GetString().Should().Be("$.stations[0]");
    }

    [Fact]
    public void Check_NamesWithControlCharactersOrTooLong_EachItemNamedAndNoControlCharacterPrinted()
    {
        var file = FileIn("line.opproj");
        var json = System.Text.Json.Nodes.JsonNode.Parse(File.ReadAllText(ProjectCommandTests.SamplePath()))!;
        json["stations"]![0]!["name"] = "Fil\u001b[31mler\u0000";
        json["stations"]![0]!["tags"]![0]!["symbol"] = "Bottle\u0007Count";
        json["stations"]![0]!["alarms"]![0]!["text"] = new string('E', 300);
        File.WriteAllText(file, json.ToJsonString());

        var run = Run("project", "check", file);

        run.Code.Should().Be(1);
        run.Out.Should().NotContainAny("\u001b", "\u0000", "\u0007");
        run.Out.Split('\n', StringSplitOptions.RemoveEmptyEntries).Should().Equal(
            $"{file}: $.stations[0].name: the station name 'Fil<16#1B>[31mler<16#00>' holds control characters (16#1B, 16#00), which a screen does not show or takes as commands; remove them",
            $"{file}: $.stations[0].tags[0].symbol: the symbol 'Bottle<16#07>Count' holds control characters (16#07), which a screen does not show or takes as commands; remove them",
            $"{file}: $.stations[0].alarms[0].text: the alarm text '{new string('E', 40)}...' is 300 characters long; at most 128: the alarm banner shows it on one line in large type",
            $"{file}: 3 problems");
    }

    [Fact]
    public void New_NameWithAnEscape_RefusedAndNothingWritten()
    {
        var file = FileIn("line.opproj");

        var run = Run("project", "new", "--cpu", "224", "--name", "Line\u001b[2J3", "-o", file);

        run.Code.Should().Be(1);
        run.Error.Should().Be($"opanel: the project name 'Line<16#1B>[2J3' holds control characters (16#1B), which a screen does not show or takes as commands; remove them; {file} not written" + Environment.NewLine);
        File.Exists(file).Should().BeFalse();
    }

    [Fact]
    public void New_ForceOntoAReadOnlyFile_RefusedKeepingTheFileAndItsBak()
    {
        var file = FileIn("line.opproj");
        File.WriteAllText(file, "keep me");
        File.WriteAllText(file + ".bak", "older");
        File.SetAttributes(file, FileAttributes.ReadOnly);

        // Decided by the mode (0444: chmod a-w), not by EACCES: the tests run as root, whom the kernel lets write it.
        File.GetAttributes(file).Should().HaveFlag(FileAttributes.ReadOnly);
        var run = Run("project", "new", "--cpu", "224", "-o", file, "--force");
        File.SetAttributes(file, FileAttributes.Normal);

        run.Code.Should().Be(1);
        run.Error.Should().Be($"opanel: {file}: cannot save the file: {file} is read-only: nothing written; make it writable to replace it "
            + "(chmod u+w on Linux, clear Read-only in its Properties on Windows), or save elsewhere" + Environment.NewLine);
        File.ReadAllText(file).Should().Be("keep me");
        File.ReadAllText(file + ".bak").Should().Be("older", "the .bak is renewed only when the replacement goes ahead");
    }

    public void Dispose()
    {
        foreach (var file in Directory.EnumerateFiles(_folder))
        {
            File.SetAttributes(file, FileAttributes.Normal);
        }

        Directory.Delete(_folder, recursive: true);
    }

    private string FileIn(string name) => Path.Combine(_folder, name);

    private (int Code, string Out, string Error) Run(params string[] args)
    {
        using var output = new StringWriter();
        using var error = new StringWriter();
        var code = OpanelApp.Run([.. args, "--log-dir", Path.Combine(_folder, "logs")], output, error);
        return (code, output.ToString().Replace("\r\n", "\n", StringComparison.Ordinal), error.ToString());
    }
}
