using System.Diagnostics;
using System.Text.RegularExpressions;
using OperatorPanel.Cli;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Ppi;
using OperatorPanel.Core.Ppi.S7;
using OperatorPanel.Core.Transport;
using OperatorPanel.TestKit;

namespace OperatorPanel.Cli.Tests.Commands;

/// <summary>
/// <c>opanel simulate</c> on one end of a socat pty pair and the link verbs on the other: the whole serial path in real
/// time (bounded: the simulation stops itself after --duration).
/// </summary>
[Collection(RealTimeSerialCollection.Name)]
public sealed class SimulateCommandTests
{
    private static readonly TimeSpan StartLimit = TimeSpan.FromSeconds(3);

    [Theory]
    [InlineData("stl")]
    [InlineData("reference")]
    public async Task Simulate_OnAPty_AnswersIdentifyWriteAndReadFromTheOtherEnd(string model)
    {
        using var pty = await SocatPtyPair.StartAsync();
        using var simulatorOut = new StringWriter();
        var output = TextWriter.Synchronized(simulatorOut);
        string[] args = ["simulate", "--cpu", "226", "--station", "3", "--station", "4", "--device", pty.PathA, "--baud", "19200", "--duration", "5", "--model", model, "--log-dir", LogDir];
        var simulator = Task.Run(() => OpanelApp.Run(args, output, TextWriter.Null));
        await WaitForAsync(() => Text(output, simulatorOut).Contains("simulating", StringComparison.Ordinal));
        // Real time on a possibly loaded machine: allow a long "scan" so a stalled thread costs no retry.
        string[] line = ["--device", pty.PathB, "--baud", "19200", "--scan-ms", "1000"];

        var identify = CliRunner.Run(["identify", "--station", "4", "--cpu", "224", .. line]);
        var write = CliRunner.Run(["write", "VW200=4660", "Q1.1=on", "--station", "3", .. line]);
        var read = CliRunner.Run(["read", "VW200", "VB9000", "Q1.1", "--station", "3", "--cpu", "226", .. line]);
        var silent = CliRunner.Run(["read", "VB0", "--station", "9", "--device", pty.PathB, "--baud", "19200"]);

        identify.ExitCode.Should().Be(1, identify.Error); // a CPU 226 asked for as 224: mismatch
        identify.Out.Should().Contain("generated for CPU 226 (Current)").And.Contain("SMB6          16#90: CPU 226")
            .And.Contain("cpu check     MISMATCH with CPU 224: the PLC reports SMB6 16#90 (CPU 226), CPU 224 has 16#20");
        write.ExitCode.Should().Be(0, write.Error);
        write.Out.Split(Environment.NewLine, StringSplitOptions.RemoveEmptyEntries).Select(ConfirmedPart).Should().Equal(
            "VW200    0 -> 4660  confirmed", "Q1.1     0 -> 1  confirmed");
        read.ExitCode.Should().Be(0, read.Error);
        read.Out.Split('\n', StringSplitOptions.RemoveEmptyEntries).Should().Equal(
            "VW200    4660        16#1234      good",
            "VB9000   0           16#00        good", // past a CPU 224's V: station 3 is the CPU 226
            "Q1.1     1                        good"); // the panel owns Q1.1 now; the demo process leaves it alone
        silent.ExitCode.Should().Be(2);
        silent.Error.Should().StartWith($"opanel: station 9 on {pty.PathB}: no valid reply to v3 Read after ")
            .And.Contain("opanel: nothing answers as station 9: check that the PLC is in RUN with its mode switch at RUN")
            .And.Contain("handler was generated for station 9 at 19200 8N1");

        (await simulator).Should().Be(0);
        var summary = Text(output, simulatorOut);
        summary.Should().StartWith($"simulating CPU 226 at stations 3, 4 on {pty.PathA} 19200 8N1, protocol 3 full handler, END_TIMEOUT_MS 2, model {model}, demo process on");
        summary.Should().MatchRegex($@"stopped serving {Regex.Escape(pty.PathA)}: \d+ frames received, \d+ answered");
    }

    [Fact]
    public async Task SimulatePpi_OnAPty_ReadsAndWritesTheCpuWithoutAHandler()
    {
        using var pty = await SocatPtyPair.StartAsync();
        using var simulatorOut = new StringWriter();
        var output = TextWriter.Synchronized(simulatorOut);
        string[] args = ["simulate", "--ppi", "--cpu", "226", "--station", "2", "--device", pty.PathA, "--baud", "19200", "--duration", "4", "--no-process", "--log-dir", LogDir];
        var simulator = Task.Run(() => OpanelApp.Run(args, output, TextWriter.Null));
        await WaitForAsync(() => Text(output, simulatorOut).Contains("simulating", StringComparison.Ordinal));
        await using var panel = new SerialPortTransport(new SerialSettings { PortName = pty.PathB, BaudRate = 19200, Parity = Parity.Even });
        var master = new PpiMaster(panel, PpiMasterOptions.ForBaud(19200) with { ReplyTimeout = TimeSpan.FromMilliseconds(800), AnswerTimeout = TimeSpan.FromSeconds(3) });
        await panel.OpenAsync(default);
        PpiAddressing.TryWrite(PlcAddress.Parse("VW200"), 4660, out var write, out _);

        var codes = await master.WriteAsync(new Station(2), [write!], default);
        var results = await master.ReadAsync(new Station(2), [S7Item.Bytes(S7Area.V, 200, 2), S7Item.Bytes(S7Area.SM, 6, 1)], default);

        codes.Should().Equal(S7ReturnCode.Success);
        results.Select(r => Convert.ToHexString(r.Data.AsSpan())).Should().Equal("1234", "90");
        (await simulator).Should().Be(0);
        var text = Text(output, simulatorOut);
        text.Should().StartWith($"simulating CPU 226 at station 2 on {pty.PathA} 19200 8E1, no handler, PPI at the station addresses, model stl, demo process off");
        text.Should().Contain($"stopped serving {pty.PathA}: 4 PPI telegrams answered");
    }

    [Fact]
    public async Task ReadWriteIdentifyPpi_SimulatedCpuWithoutHandler_WorkInRunAndInStop()
    {
        using var pty = await SocatPtyPair.StartAsync();
        using var simulatorOut = new StringWriter();
        var output = TextWriter.Synchronized(simulatorOut);
        string[] args = ["simulate", "--ppi", "--cpu", "224", "--station", "2", "--device", pty.PathA, "--baud", "19200", "--duration", "8", "--no-process", "--log-dir", LogDir];
        var simulator = Task.Run(() => OpanelApp.Run(args, output, TextWriter.Null));
        await WaitForAsync(() => Text(output, simulatorOut).Contains("simulating", StringComparison.Ordinal));
        string[] line = ["--device", pty.PathB, "--ppi", "--baud", "19200", "--cpu", "224", "--scan-ms", "1000"];

        var write = CliRunner.Run(["write", "VB100=66", "MW4=4660", "Q0.1=on", .. line]);
        var read = CliRunner.Run(["read", "VB100", "I0.0", "MW4", .. line]);
        var identify = CliRunner.Run(["identify", .. line]);
        await StopOverPpiAsync(pty.PathB);
        var readInStop = CliRunner.Run(["read", "VB100", "MW4", .. line]);
        var writeInStop = CliRunner.Run(["write", "MW4=7", .. line]);

        write.ExitCode.Should().Be(0, write.Out + write.Error);
        // Each write is confirmed: straight from the CPU's answer or, when a stalled host missed that answer (seen at a
        // load average of 30), by the read-back that follows; either way once, with the value the CPU holds.
        write.Out.Split(Environment.NewLine, StringSplitOptions.RemoveEmptyEntries).Select(ConfirmedPart).Should().Equal(
            "VB100    0 -> 66  confirmed", "MW4      0 -> 4660  confirmed", "Q0.1     0 -> 1  confirmed");
        read.ExitCode.Should().Be(0, read.Error);
        read.Out.Split(Environment.NewLine, StringSplitOptions.RemoveEmptyEntries).Should().Equal(
            "VB100    66          16#42        good", "I0.0     0                        good", "MW4      4660        16#1234      good");
        identify.ExitCode.Should().Be(0, identify.Error);
        identify.Out.Should().Contain("link          PPI 19200 8E1, no handler").And.Contain("SMB6          16#20: CPU 224 or CPU 224XP")
            .And.Contain("mode          unknown over PPI").And.Contain("cpu check     ok: matches CPU 224");
        readInStop.ExitCode.Should().Be(0, readInStop.Error);
        readInStop.Out.Should().Contain("MW4      4660        16#1234      good");
        writeInStop.ExitCode.Should().Be(0, writeInStop.Out + writeInStop.Error);
        writeInStop.Out.Should().StartWith("MW4      4660 -> 7  confirmed");
        (await simulator).Should().Be(0);
    }

    /// <summary>A write's line up to "confirmed", without the " (reply lost, read back): ..." a lost answer adds.</summary>
    private static string ConfirmedPart(string line) =>
        line.Split(" (reply lost, read back)", 2)[0];

    /// <summary>The S7 STOP job (docs/ppi.md section 5) from a master of the test's own: the panel offers no STOP over PPI.</summary>
    private static async Task StopOverPpiAsync(string device)
    {
        await using var port = new SerialPortTransport(new SerialSettings { PortName = device, BaudRate = 19200, Parity = Parity.Even });
        await port.OpenAsync(default);
        var master = new PpiMaster(port, PpiMasterOptions.ForBaud(19200) with { ReplyTimeout = TimeSpan.FromMilliseconds(800), AnswerTimeout = TimeSpan.FromSeconds(3) });
        await master.ExchangeAsync(new Station(2), S7JobCodec.Stop(1), default);
    }

    [Theory]
    [InlineData("--baud", "38400")]
    [InlineData("--parity", "none")]
    [InlineData("--data-bits", "7")]
    [InlineData("--model", "reference")]
    public void SimulatePpi_OptionPpiCannotHave_ExitsOneWithTheReason(string option, string value)
    {
        var run = CliRunner.Run("simulate", "--ppi", "--cpu", "224", "--station", "2", "--device", "/dev/null", option, value);

        run.ExitCode.Should().Be(1);
        run.Error.Should().MatchRegex("PPI|--ppi");
    }

    [Fact]
    public void Simulate_MissingDevice_ExitsTwo()
    {
        var run = CliRunner.Run("simulate", "--cpu", "224", "--station", "2", "--device", "/dev/opanel-no-such-port", "--duration", "1");

        run.ExitCode.Should().Be(2);
        run.Error.Should().StartWith("opanel: serial port /dev/opanel-no-such-port: open failed").And.Contain("the simulated PLCs stopped")
            .And.NotContain("PortUnavailable");
    }

    [Theory]
    [InlineData("--station", "2", "--model", "plc")]
    [InlineData("--station", "2", "--station", "2")]
    [InlineData("--station", "127", "--reply-delay", "5")]
    [InlineData("--station", "2", "--reply-delay", "0")]
    [InlineData("--station", "2", "--duration", "-1")]
    public void Simulate_BadOption_ExitsOne(string option1, string value1, string option2, string value2)
    {
        CliRunner.Run("simulate", "--cpu", "224", "--device", "/dev/null", option1, value1, option2, value2).ExitCode.Should().Be(1);
    }

    [Fact]
    public async Task Simulate_ProjectWithTwoCpus_ServesEachStationWithItsOwnCpuOnOneDevice()
    {
        using var pty = await SocatPtyPair.StartAsync();
        var project = TwoCpuProject(pty.PathB);
        using var simulatorOut = new StringWriter();
        var output = TextWriter.Synchronized(simulatorOut);
        string[] args = ["simulate", "--project", project, "--device", pty.PathA, "--duration", "4", "--no-process", "--log-dir", LogDir];
        var simulator = Task.Run(() => OpanelApp.Run(args, output, TextWriter.Null));
        await WaitForAsync(() => Text(output, simulatorOut).Contains("simulating", StringComparison.Ordinal));
        string[] line = ["--device", pty.PathB, "--scan-ms", "1000"];

        var filler = CliRunner.Run(["identify", "--station", "2", "--cpu", "224", .. line]);
        var capper = CliRunner.Run(["identify", "--station", "3", "--cpu", "226", .. line]);

        filler.ExitCode.Should().Be(0, filler.Error);
        filler.Out.Should().Contain("generated for CPU 224 (Current)").And.Contain("STOP          in the handler");
        capper.ExitCode.Should().Be(0, capper.Error);
        capper.Out.Should().Contain("generated for CPU 226 (Current)").And.Contain("STOP          not in the handler");
        (await simulator).Should().Be(0);
        Text(output, simulatorOut).Should().StartWith(
            $"simulating station 2 (CPU 224), station 3 (CPU 226) on {pty.PathA} 9600 8N1, protocol 3 handlers: station 2 full with STOP, station 3 full, END_TIMEOUT_MS 4, model stl, demo process off");
        File.Delete(project);
    }

    [Fact]
    public async Task Simulate_ProjectHandlerVFirst_RunsTheHandlerWhereTheProjectSays()
    {
        using var pty = await SocatPtyPair.StartAsync();
        var project = Path.Combine(Path.GetTempPath(), $"opanel-simulate-{Guid.NewGuid():N}.opproj");
        File.WriteAllText(project, $$"""
            {
              "schemaVersion": 1,
              "name": "Moved handler",
              "refresh": { "mode": "continuous", "minimumPeriodMs": 100 },
              "stations": [ { "name": "Filler", "address": 2, "cpu": { "model": "224" }, "link": { "port": "{{pty.PathB}}" }, "handlerVFirst": 1000 } ]
            }
            """);
        using var simulatorOut = new StringWriter();
        var output = TextWriter.Synchronized(simulatorOut);
        string[] args = ["simulate", "--project", project, "--device", pty.PathA, "--duration", "3", "--no-process", "--log-dir", LogDir];
        var simulator = Task.Run(() => OpanelApp.Run(args, output, TextWriter.Null));
        await WaitForAsync(() => Text(output, simulatorOut).Contains("simulating", StringComparison.Ordinal));

        var identify = CliRunner.Run(["identify", "--station", "2", "--cpu", "224", "--device", pty.PathB, "--scan-ms", "1000"]);

        identify.ExitCode.Should().Be(0, identify.Error);
        identify.Out.Should().Contain("handler V     VB1000-VB1605 (606 bytes");
        (await simulator).Should().Be(0);
        File.Delete(project);
    }

    [Theory]
    [InlineData("--cpu", "224", "with --project each station's CPU and the bus's line settings come from the project; leave out --cpu")]
    [InlineData("--baud", "19200", "with --project each station's CPU and the bus's line settings come from the project; leave out --baud")]
    [InlineData("--station", "7", "station 7 is not in {0} (it has 2 Filler, 3 Capper)")]
    public void Simulate_ProjectWithAConflictingOption_SaysWhichAndExitsOne(string option, string value, string message)
    {
        var project = TwoCpuProject("COM3");

        var run = CliRunner.Run("simulate", "--project", project, "--device", "/dev/null", option, value);

        run.ExitCode.Should().Be(1);
        run.Error.Should().Be($"opanel: {string.Format(System.Globalization.CultureInfo.InvariantCulture, message, project)}{Environment.NewLine}");
        File.Delete(project);
    }

    [Fact]
    public void Simulate_NeitherCpuNorProject_SaysWhatToGive()
    {
        var run = CliRunner.Run("simulate", "--device", "/dev/null");

        run.ExitCode.Should().Be(1);
        run.Error.Should().Be("opanel: give the simulated PLCs with --cpu and --station (e.g. --cpu 224 --station 2), or a project's bus with --project"
            + Environment.NewLine);
    }

    [Fact]
    public void Simulate_NoDevice_AsksForTheDeviceToServeOnWithoutOfferingDemo()
    {
        var run = CliRunner.Run("simulate", "--cpu", "224", "--station", "2");

        run.ExitCode.Should().Be(1);
        run.Error.Should().Be("opanel: give the serial device to serve on with --device (e.g. --device /dev/pts/N, one end of a socat pair, or --device COM4)"
            + Environment.NewLine);
    }

    /// <summary>Filler: CPU 224 station 2 with STOP; Capper: CPU 226 station 3; both on <paramref name="port"/>.</summary>
    private static string TwoCpuProject(string port)
    {
        var file = Path.Combine(Path.GetTempPath(), $"opanel-simulate-{Guid.NewGuid():N}.opproj");
        File.WriteAllText(file, $$"""
            {
              "schemaVersion": 1,
              "name": "Packing line",
              "refresh": { "mode": "continuous", "minimumPeriodMs": 100 },
              "stations": [
                { "name": "Filler", "address": 2, "cpu": { "model": "224" }, "link": { "port": "{{port}}" }, "allowStop": true },
                { "name": "Capper", "address": 3, "cpu": { "model": "226" }, "link": { "port": "{{port}}" } }
              ]
            }
            """);
        return file;
    }

    private static string LogDir => Path.Combine(Path.GetTempPath(), "opanel-tests-logs");

    private static string Text(TextWriter synchronized, StringWriter inner)
    {
        // TextWriter.Synchronized locks the wrapper itself; read under the same lock.
        lock (synchronized)
        {
            return inner.ToString();
        }
    }

    private static async Task WaitForAsync(Func<bool> condition)
    {
        // Process start-up only: the one place real waiting is allowed, bounded by StartLimit.
        var watch = Stopwatch.StartNew();
        while (!condition())
        {
            watch.Elapsed.Should().BeLessThan(StartLimit, "the simulator should have started");
            await Task.Delay(20);
        }
    }
}
