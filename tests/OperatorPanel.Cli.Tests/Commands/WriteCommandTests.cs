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
        // The protocol 3 handler does not serve SM (docs/protocol.md section 1.3, 82): the panel says so without asking it.
        var run = CliRunner.Run("write", "SMB34=9", "--demo");

        run.ExitCode.Should().Be(1);
        run.Out.Should().BeEmpty();
        run.Error.Should().Contain("SMB34: the Freeport handler does not serve SM").And.Contain("nothing written");
    }

    [Fact]
    public void Write_TheHandlersOwnVBytes_AreRefusedBeforeAnythingIsSent()
    {
        // VB8000 is inside the demo CPU 224's full handler (VB7586-VB8191): the PLC would refuse it with 83 once sent.
        var run = CliRunner.Run("write", "VW200=1", "VB8000=9", "--demo");

        run.ExitCode.Should().Be(1);
        run.Out.Should().BeEmpty("nothing is written when one assignment is refused");
        run.Error.Should().Be("opanel: VB8000 is in the handler's own V bytes VB7586-VB8191 (where generate puts the full handler's buffer, "
            + "work bytes and list by default; IDENTIFY says where a station's are); nothing written" + Environment.NewLine);
    }

    [Theory]
    [InlineData("VD100=1.5e-50", "opanel: VD100: 1.5e-50 is too close to 0 for a REAL (a REAL holds 0 and numbers from ±1.175495E-38 to ±3.402823E+38): "
        + "it would be stored as 0; write 0 or a number inside that range; nothing written")]
    [InlineData("VD100=-2e39", "opanel: VD100: -2e39 is too large for a REAL (a REAL holds 0 and numbers from ±1.175495E-38 to ±3.402823E+38); "
        + "write a number inside that range; nothing written")]
    [InlineData("VD100=-1e-40", "opanel: VD100: -1e-40 is too close to 0 for a REAL (a REAL holds 0 and numbers from ±1.175495E-38 to ±3.402823E+38): "
        + "it would be stored as -1E-40; write 0 or a number inside that range; nothing written")] // a denormal, outside the manual's range
    public void Write_RealTheS7200CannotHold_IsRefusedBeforeAnythingIsSent(string assignment, string message)
    {
        var run = CliRunner.Run("write", assignment, "--demo");

        run.ExitCode.Should().Be(1, "bad input");
        run.Out.Should().BeEmpty();
        run.Error.Should().Be(message + Environment.NewLine);
    }

    [Fact]
    public void Write_RealThatOnlyLosesPrecision_IsConfirmedAsTheRealThePlcHolds()
    {
        var run = CliRunner.Run("write", "VD300=1.23456789", "VD304=-0.0", "--demo");

        run.ExitCode.Should().Be(0, run.Error);
        run.Out.Split('\n', StringSplitOptions.RemoveEmptyEntries).Should().Equal(
            "VD300    0 -> 1.2345679  confirmed",
            "VD304    0 -> -0  confirmed");
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
