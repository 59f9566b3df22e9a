using System.Text.Json;

namespace OperatorPanel.Cli.Tests;

public sealed class CpusCommandTests
{
    [Fact]
    public void Cpus_Text_ListsEveryProfileWithItsRanges()
    {
        var (exit, output, _) = CliRunner.Run("cpus");

        exit.Should().Be(0);
        output.Should().Contain("CPU 224XP (Current)").And.Contain("V VB0-VB10239").And.Contain("SM SMB0-SMB549");
        output.Should().Contain("CPU 224 (Early)").And.Contain("V VB0-VB5119");
        output.Should().Contain("115200=110").And.Contain("300=111");
    }

    [Fact]
    public void Cpus_Json_GivesAreasAndBaudCodes()
    {
        var (exit, output, _) = CliRunner.Run("cpus", "--json");

        exit.Should().Be(0);
        using var json = JsonDocument.Parse(output);
        var cpu226 = json.RootElement.EnumerateArray().Single(e => e.GetProperty("model").GetString() == "226");
        cpu226.GetProperty("communicationPorts").GetInt32().Should().Be(2);
        cpu226.GetProperty("smb6").GetString().Should().Be("16#90");
        cpu226.GetProperty("areas").EnumerateArray()
            .Single(a => a.GetProperty("area").GetString() == "V").GetProperty("bytes").GetInt32().Should().Be(10240);
    }
}
