using System.Text.Json;

namespace OperatorPanel.Cli.Tests.Commands;

/// <summary><c>opanel write</c> against the in-process demo PLC.</summary>
public sealed class WriteCommandTests
{
    [Fact]
    public void Write_Demo_ConfirmsEachWriteWithOldAndNewValue()
    {
        var run = CliRunner.Run("write", "VW200=1234", "VW202=-5", "VB204=16#2a", "VD206=12.5", "VD210='AB12'", "M5.3=on", "--demo");

        run.ExitCode.Should().Be(0, run.Out + run.Error);
        run.Out.Split('\n', StringSplitOptions.RemoveEmptyEntries).Should().Equal(
            "VW200    0 -> 1234  confirmed",
            "VW202    0 -> -5  confirmed",
            "VB204    16#00 -> 16#2A  confirmed",
            "VD206    0 -> 12.5  confirmed",
            "VD210    .... -> AB12  confirmed",
            "M5.3     0 -> 1  confirmed");
    }

    [Fact]
    public void Write_DemoJson_GivesOldNewAndOutcome()
    {
        var run = CliRunner.Run("write", "VW200=7", "--demo", "--json");

        using var json = JsonDocument.Parse(run.Out);
        var write = json.RootElement[0];
        write.GetProperty("address").GetString().Should().Be("VW200");
        write.GetProperty("old").GetString().Should().Be("0");
        write.GetProperty("new").GetString().Should().Be("7");
        write.GetProperty("outcome").GetString().Should().Be("confirmed");
    }

    [Fact]
    public void Write_InputByte_IsRefusedWithExitOne()
    {
        var run = CliRunner.Run("write", "IB0=1", "--demo");

        run.ExitCode.Should().Be(1);
        run.Error.Should().Contain("IB0").And.Contain("nothing written");
    }

    [Fact]
    public void Write_SmOverFreeport_IsRefusedBeforeAnythingIsSent()
    {
        // The protocol 3 handler never writes SM (docs/protocol.md section 3, 83): the panel says so without asking it.
        var run = CliRunner.Run("write", "SMB34=9", "--demo");

        run.ExitCode.Should().Be(1);
        run.Out.Should().BeEmpty();
        run.Error.Should().Contain("SMB34: the Freeport handler never writes SM (it refuses with 83").And.Contain("nothing written");
    }

    [Fact]
    public void Write_TheHandlersOwnVBytes_AreRefusedByThePlcWithExitOne()
    {
        // VB8000 is inside the demo CPU 224's full handler (VB7586-VB8191): the PLC refuses it, 83.
        var run = CliRunner.Run("write", "VB8000=9", "--demo");

        run.ExitCode.Should().Be(1);
        run.Out.Should().Contain("VB8000   0 -> 9  failed: station 2 refused the write: 83: the PLC refuses writes there (inputs, SM, an area the handler's write mask leaves out, or the handler's own V bytes)");
    }

    [Theory]
    [InlineData("VB100=300", "VB100: 300 is outside 0..255")]
    [InlineData("VW100=1.5", "VW100: a REAL (Float) needs a double word")]
    [InlineData("VD100='ABC'", "exactly 4 ASCII characters")]
    [InlineData("M0.0=2", "is not a bit value")]
    [InlineData("VB100", "write ADDR=VALUE")]
    public void Write_BadValue_ExitsOneAndWritesNothing(string assignment, string message)
    {
        var run = CliRunner.Run("write", "VW200=1", assignment, "--demo");

        run.ExitCode.Should().Be(1);
        run.Error.Should().Contain(message).And.Contain("nothing written");
        run.Out.Should().NotContain("confirmed");
    }

    [Fact]
    public void Write_InputBitWithoutCpu_IsRefusedBeforeThePortIsOpened()
    {
        var run = CliRunner.Run("write", "I0.0=1", "--device", "/dev/opanel-no-such-port");

        run.ExitCode.Should().Be(1, "bad input, found before anything is read or sent (a port failure would be 2)");
        run.Error.Should().Be("opanel: I0.0: inputs are read from the field; the panel never writes them; nothing written" + Environment.NewLine);
    }

    [Fact]
    public void Write_BadInputJson_KeepsTheMessagesApostrophesReadable()
    {
        var run = CliRunner.Run("write", "I0.0=1", "--demo", "--json");

        run.ExitCode.Should().Be(1);
        run.Out.Should().Contain("\"error\": \"I0.0: inputs are read from the field; the panel never writes them; nothing written\"");
    }

    [Fact]
    public void Write_MissingDevice_ExitsTwoAndWritesNothing()
    {
        var device = Path.Combine(Path.GetTempPath(), "opanel-no-such-port-" + Guid.NewGuid().ToString("N"));

        var run = CliRunner.Run("write", "VW200=1", "--device", device);

        run.ExitCode.Should().Be(2);
        run.Error.Should().Contain($"serial port {device}: open failed").And.Contain("; nothing written")
            .And.Contain($"check the port name ({device})");
    }
}
