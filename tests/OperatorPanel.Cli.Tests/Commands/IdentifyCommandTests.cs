using System.Text.Json;

namespace OperatorPanel.Cli.Tests.Commands;

/// <summary><c>opanel identify</c> against the in-process demo PLC.</summary>
public sealed class IdentifyCommandTests
{
    [Fact]
    public void Identify_Demo_DecodesTheReply()
    {
        var run = CliRunner.Run("identify", "--demo", "--station", "7");

        run.ExitCode.Should().Be(0, run.Error);
        run.Out.Should().Contain("station       7 on demo")
            .And.Contain("protocol      version 3, handler revision 1, full handler, at most 16 bytes per READ (MAX_DATA)")
            .And.Contain("generated for CPU 224 (Current)")
            .And.Contain("SMB6          16#20: CPU 224 or CPU 224XP")
            .And.Contain("mode switch   RUN")
            .And.Contain("write mask    16#1C: Q M V")
            .And.Contain("FEATURES      16#03: list, STOP")
            .And.Contain("list          32 items, 128 bytes (LIST_ITEMS, LIST_BYTES): one READ LIST a refresh")
            .And.Contain("requests      at most 137 bytes (MAX_REQUEST)")
            .And.Contain("end time-out  4 ms (END_TIMEOUT_MS")
            .And.Contain("handler V     VB7586-VB8191 (606 bytes, V_FIRST/V_BYTES: never written by the panel)")
            .And.Contain("STOP          in the handler (FEATURES bit 0): opanel stop can put it into STOP")
            .And.Contain("cpu check     ok: matches CPU 224");
        run.Out.Should().MatchRegex(@"scan          last \d ms, min \d ms, max \d ms");
    }

    [Theory]
    [InlineData("stl")]
    [InlineData("reference")]
    public void Identify_DemoEitherModel_AnswersTheSame(string model)
    {
        var run = CliRunner.Run("identify", "--demo", "--cpu", "226", "--station", "5", "--baud", "19200", "--model", model);

        run.ExitCode.Should().Be(0, run.Error);
        run.Out.Should().Contain("station       5 on demo").And.Contain("generated for CPU 226 (Current)").And.Contain("mode switch   RUN");
    }

    [Fact]
    public void Identify_DemoHandlerCannotBeGenerated_ExitsOneNamingTheDiagnostic()
    {
        var run = CliRunner.Run("identify", "--demo", "--cpu", "224", "--revision", "early", "--baud", "115200");

        run.ExitCode.Should().Be(1);
        run.Error.Should().Contain("the handler cannot be generated: STL").And.Contain("115200");
    }

    [Fact]
    public void Identify_DemoJson_HasTheFields()
    {
        var run = CliRunner.Run("identify", "--demo", "--cpu", "222", "--json");

        using var json = JsonDocument.Parse(run.Out);
        json.RootElement.GetProperty("smb6").GetString().Should().Be("16#00");
        json.RootElement.GetProperty("writableAreas").EnumerateArray().Select(a => a.GetString()).Should().Equal(["Q", "M", "V"], "protocol 3 never writes I or SM");
        json.RootElement.GetProperty("protocolVersion").GetInt32().Should().Be(3);
        (json.RootElement.GetProperty("listItems").GetInt32(), json.RootElement.GetProperty("listBytes").GetInt32(), json.RootElement.GetProperty("maxRequest").GetInt32())
            .Should().Be((32, 128, 137));
        json.RootElement.GetProperty("endTimeoutMs").GetInt32().Should().Be(4, "one character at 9600 baud + 2 ms, at least the cable's 4 ms turnaround");
        json.RootElement.GetProperty("cpuMismatch").ValueKind.Should().Be(JsonValueKind.Null);
    }

    [Fact]
    public void Identify_MissingDevice_ExitsTwo()
    {
        var run = CliRunner.Run("identify", "--device", "/dev/opanel-no-such-port");

        run.ExitCode.Should().Be(2);
        run.Error.Should().StartWith("opanel: station 2: serial port /dev/opanel-no-such-port: open failed")
            .And.Contain("opanel: check the port name (/dev/opanel-no-such-port)");
    }
}
