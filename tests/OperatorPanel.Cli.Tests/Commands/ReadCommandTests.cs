using System.Text.Json;

namespace OperatorPanel.Cli.Tests.Commands;

/// <summary><c>opanel read</c> against the in-process demo PLC (real time, a few exchanges of 5 ms reply delay).</summary>
public sealed class ReadCommandTests
{
    [Fact]
    public void Read_Demo_PrintsCanonicalAddressValueHexAndQuality()
    {
        var run = CliRunner.Run("read", "vw200", "I0.4", "VB0", "--demo");

        run.ExitCode.Should().Be(0, run.Error);
        run.Out.Split('\n', StringSplitOptions.RemoveEmptyEntries).Should().Equal(
            "VW200    0           16#0000      good",
            "I0.4     1                        good", //    demo process: mode selector in AUTO, always on
            "VB0      0           16#00        good");
    }

    [Fact]
    public void Read_DemoOverPpi_AnalogTimerCounterAndSBits_ReadGood()
    {
        // The demo's PPI CPU runs an empty program, so every value is 0: the values themselves are proven in
        // IntegrationTests/Ppi (PpiBusTests, PpiSerialTests); here the CLI accepts and reads them over PPI.
        var run = CliRunner.Run("read", "AIW0", "T37", "C5", "SB0", "--demo", "--ppi");

        run.ExitCode.Should().Be(0, run.Error);
        run.Out.Split('\n', StringSplitOptions.RemoveEmptyEntries).Should().Equal(
            "AIW0     0           16#0000      good",
            "T37      0           16#0000      good",
            "C5       0           16#0000      good",
            "SB0      0           16#00        good");
    }

    [Fact]
    public void Read_DemoJson_PrintsAnArray()
    {
        var run = CliRunner.Run("read", "VD120", "Q0.0", "--demo", "--cpu", "226", "--json");

        using var json = JsonDocument.Parse(run.Out);
        json.RootElement.GetArrayLength().Should().Be(2);
        json.RootElement[0].GetProperty("address").GetString().Should().Be("VD120");
        json.RootElement[0].GetProperty("value").GetInt64().Should().Be(0x43FA0000, "the demo's fill setpoint, a REAL of 500 ml");
        json.RootElement[0].GetProperty("hex").GetString().Should().Be("16#43FA0000");
        json.RootElement[1].GetProperty("quality").GetString().Should().Be("good");
    }

    [Theory]
    [InlineData("VB99999", "byte number")]
    [InlineData("AIW0", "AIW0: the Freeport link reads only I, Q, M and V: its handler reaches memory through pointers, and an S7-200 pointer cannot reach analog values; copy the analog value to V in the PLC program (MOVW AIW0, VW100)")]
    [InlineData("T37", "T37: the Freeport link reads only I, Q, M and V: its handler leaves timers out to stay small; copy the current value to V in the PLC program (MOVW T37, VW100) and watch that, or read the station over PPI")]
    [InlineData("VB8192", "VB8192")]
    [InlineData("SMB6", "SMB6: the Freeport link reads only I, Q, M and V: its handler reaches memory through pointers, and no S7-200 manual page found says a pointer reaches SM; copy the SM bytes to V in the PLC program (MOVB SMB6, VB100) and watch that, or read the station over PPI")]
    public void Read_BadAddress_ExitsOneWithTheMessage(string address, string message)
    {
        var run = CliRunner.Run("read", address, "--demo");

        run.ExitCode.Should().Be(1);
        run.Error.Should().Contain(message);
        run.Out.Should().BeEmpty();
    }

    [Fact]
    public void Read_MissingDevice_ExitsTwoNamingThePortAndWhatToCheck()
    {
        var device = Path.Combine(Path.GetTempPath(), "opanel-no-such-port-" + Guid.NewGuid().ToString("N"));

        var run = CliRunner.Run("read", "VB0", "--device", device, "--station", "5");

        run.ExitCode.Should().Be(2);
        var lines = run.Error.Split(Environment.NewLine, StringSplitOptions.RemoveEmptyEntries);
        lines.Should().HaveCount(2, "what happened, then what to check; the log's warnings are not echoed again");
        lines[0].Should().StartWith($"opanel: station 5: serial port {device}: open failed");
        lines[1].Should().Be($"opanel: check the port name ({device}), that the cable or USB adapter is plugged in, and that no other "
            + "program (Micro/WIN, another opanel) has the port open");
        run.Error.Should().NotContain("PortUnavailable", "the kind is for scripts (--json), not for the technician");
    }

    [Fact]
    public void Read_MissingDeviceJson_GivesErrorKindAndHint()
    {
        var device = Path.Combine(Path.GetTempPath(), "opanel-no-such-port-" + Guid.NewGuid().ToString("N"));

        var run = CliRunner.Run("read", "VB0", "--device", device, "--json");

        run.ExitCode.Should().Be(2);
        using var json = JsonDocument.Parse(run.Out);
        json.RootElement.GetProperty("ok").GetBoolean().Should().BeFalse();
        json.RootElement.GetProperty("error").GetString().Should().StartWith($"station 2: serial port {device}: open failed");
        json.RootElement.GetProperty("kind").GetString().Should().Be("portUnavailable");
        json.RootElement.GetProperty("hint").GetString().Should().StartWith($"check the port name ({device})");
    }

    [Fact]
    public void Read_ProjectStationByName_TakesItsCpuAndAddressFromTheProject()
    {
        var project = Path.Combine(Path.GetTempPath(), $"opanel-read-{Guid.NewGuid():N}.opproj");
        File.WriteAllText(project, """
            {
              "schemaVersion": 1, "name": "Packing line", "refresh": { "mode": "continuous", "minimumPeriodMs": 100 },
              "stations": [
                { "name": "Filler", "address": 2, "cpu": { "model": "224" }, "link": { "port": "COM3" } },
                { "name": "Capper", "address": 3, "cpu": { "model": "226" }, "link": { "port": "COM3" } }
              ]
            }
            """);

        var capper = CliRunner.Run("read", "VB9000", "--project", project, "--station", "capper", "--demo");
        var filler = CliRunner.Run("read", "VB9000", "--project", project, "--station", "Filler", "--demo");
        var neither = CliRunner.Run("read", "VB0", "--project", project, "--demo");
        File.Delete(project);

        capper.ExitCode.Should().Be(0, capper.Error);
        capper.Out.Should().Be($"VB9000   0           16#00        good{Environment.NewLine}", "the demo simulates the project's CPU 226, whose V reaches VB10239");
        filler.ExitCode.Should().Be(1);
        filler.Error.Should().Be($"opanel: VB9000 is past the last V byte VB8191 of CPU 224; nothing read{Environment.NewLine}");
        neither.ExitCode.Should().Be(1);
        neither.Error.Should().Contain("the project has 2 stations (Filler (2), Capper (3)); choose one with --station");
    }

    [Fact]
    public void Read_WideFormattedValue_KeepsTheHexColumnOfEveryLineUnderOneAnother()
    {
        var run = CliRunner.Run("read", "VD120:binary", "VB0", "--demo");

        run.ExitCode.Should().Be(0, run.Error);
        run.Out.Split('\n', StringSplitOptions.RemoveEmptyEntries).Should().Equal(
            "VD120    2#0100_0011_1111_1010_0000_0000_0000_0000 16#43FA0000  good",
            "VB0      0                                         16#00        good");
    }

    [Fact]
    public void Read_AddressWithFormat_ShowsTheValueSoInTextAndJson()
    {
        var text = CliRunner.Run("read", "VB0:binary", "VD120:real", "--demo");
        var json = CliRunner.Run("read", "VD120:real", "--demo", "--json");

        text.ExitCode.Should().Be(0, text.Error);
        text.Out.Split('\n', StringSplitOptions.RemoveEmptyEntries).Should().Equal(
            "VB0      2#0000_0000 16#00        good",
            "VD120    500         16#43FA0000  good"); // the demo's fill setpoint, a REAL of 500 ml
        using var doc = JsonDocument.Parse(json.Out);
        doc.RootElement[0].GetProperty("value").GetUInt64().Should().Be(0x43FA0000, "the unsigned value stays for scripts");
        doc.RootElement[0].GetProperty("shown").GetString().Should().Be("500");
    }

    [Theory]
    [InlineData("VW200:real", "opanel: 'VW200:real': a REAL needs a double word such as VD100")]
    [InlineData("M0.0:hex", "opanel: 'M0.0:hex': a bit is shown as 0/1; formats are for bytes, words and double words")]
    [InlineData("VD0:bogus", "opanel: 'VD0:bogus': unknown format 'bogus'; use real, signed, unsigned, hex, binary or ascii")]
    public void Read_FormatThatDoesNotFit_ExitsOneNamingIt(string address, string message)
    {
        var run = CliRunner.Run("read", address, "--demo");

        run.ExitCode.Should().Be(1);
        run.Error.Should().Be(message + "; nothing read" + Environment.NewLine);
    }

    [Fact]
    public void Read_StationNameWithoutProject_SaysAddressesAreNumbers()
    {
        var run = CliRunner.Run("read", "VB0", "--demo", "--station", "Filler");

        run.ExitCode.Should().Be(1);
        run.Error.Should().Be($"opanel: --station 'Filler': a station address is a number 1-126 (a station's name works with --project){Environment.NewLine}");
    }

    [Theory]
    [InlineData("--station", "0")]
    [InlineData("--baud", "9601")]
    [InlineData("--data-bits", "6")]
    [InlineData("--cpu", "225")]
    public void Read_BadLinkOption_ExitsOne(string option, string value)
    {
        CliRunner.Run("read", "VB0", "--demo", option, value).ExitCode.Should().Be(1);
    }

    [Fact]
    public void Read_NoDeviceNoDemo_ExitsOneSayingHow()
    {
        var run = CliRunner.Run("read", "VB0");

        run.ExitCode.Should().Be(1);
        run.Error.Should().Contain("--device").And.Contain("--demo");
    }

    [Theory]
    [InlineData("0")]
    [InlineData("60001")]
    public void Read_ScanAllowanceOutOfRange_ExitsOneNamingTheOption(string scanMs)
    {
        var run = CliRunner.Run("read", "VB0", "--demo", "--scan-ms", scanMs);

        run.ExitCode.Should().Be(1);
        run.Error.Should().Contain($"--scan-ms {scanMs} is outside 1-60000");
    }
}
