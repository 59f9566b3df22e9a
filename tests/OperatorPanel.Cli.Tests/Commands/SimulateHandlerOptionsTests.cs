using System.Diagnostics;
using OperatorPanel.Cli;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Transport;
using OperatorPanel.TestKit;

namespace OperatorPanel.Cli.Tests.Commands;

/// <summary>
/// <c>opanel simulate</c> with the handler options <c>opanel generate</c> takes (--plc-port, --copy-bytes, --writable,
/// --char-timeout, --buffer, --sbr, --int): the simulated station runs the handler generated with them, seen over a
/// socat pty pair in real time from the panel's side.
/// </summary>
[Collection(RealTimeSerialCollection.Name)]
public sealed class SimulateHandlerOptionsTests
{
    private static readonly TimeSpan StartLimit = TimeSpan.FromSeconds(3);

    [Fact]
    public async Task Simulate_PlcPort1OnCpu226_AnswersFromThePort1HandlerWithItsEndTimeout()
    {
        using var pty = await SocatPtyPair.StartAsync();
        var simulator = await StartAsync(pty, "--cpu", "226", "--plc-port", "1", "--char-timeout", "50", "--buffer", "VB1000", "--sbr", "10", "--int", "20");

        // The port's SM bytes (SMB130, SMW192) are not read over Freeport (the handler does not serve SM); IDENTIFY
        // carries END_TIMEOUT_MS and V_FIRST the handler was generated with, and only a handler that set up port 1 answers there.
        var identify = CliRunner.Run(["identify", "--cpu", "226", "--station", "2", "--device", pty.PathB, "--scan-ms", "1000"]);

        identify.ExitCode.Should().Be(0, identify.Error);
        identify.Out.Should().Contain("end time-out  50 ms (END_TIMEOUT_MS").And.Contain("handler V     VB1000-VB1605 (606 bytes");
        (await simulator.Exit).Should().Be(0);
        simulator.Text.Should().StartWith($"simulating CPU 226 at station 2 on {pty.PathA} 9600 8N1, PLC port 1, protocol 3 full handler, END_TIMEOUT_MS 50");
    }

    [Fact]
    public async Task Simulate_WritableQ_RefusesAnMWriteWithTheHandlers83AndConfirmsAQWrite()
    {
        using var pty = await SocatPtyPair.StartAsync();
        var simulator = await StartAsync(pty, "--cpu", "224", "--writable", "Q");
        string[] line = ["--station", "2", "--device", pty.PathB, "--scan-ms", "1000"];

        var refused = CliRunner.Run(["write", "MB5=7", .. line]);
        var confirmed = CliRunner.Run(["write", "QB0=7", .. line]);

        refused.ExitCode.Should().Be(1);
        refused.Out.Should().StartWith("MB5      0 -> 7  failed: station 2 refused the write: 83");
        confirmed.ExitCode.Should().Be(0, confirmed.Error);
        confirmed.Out.Should().StartWith("QB0      0 -> 7  confirmed");
        (await simulator.Exit).Should().Be(0);
    }

    [Theory]
    [InlineData("0", true)]
    [InlineData("120", false)]
    public async Task SimulateProtocol2_CopyBytes_ZeroAnswersEveryReadChangesWithTheWholeList(string copyBytes, bool wholeListAgain)
    {
        using var pty = await SocatPtyPair.StartAsync();
        var simulator = await StartAsync(pty, "--cpu", "224", "--protocol", "2", "--copy-bytes", copyBytes);
        var station = new Station(2);
        var serial = new SerialSettings { PortName = pty.PathB };
        await using var link = new PlcLink(new SerialPortTransport(serial), LinkOptions.For(serial) with { ScanAllowance = TimeSpan.FromSeconds(1) });

        var defined = await link.ExchangeAsync(new DefineListRequest(station, 1, [new ReadItem(ProtocolArea.M, 0, 8)]), default);
        var first = await link.ExchangeAsync(new ReadChangesRequest(station, 1, full: true), default);
        var second = await link.ExchangeAsync(new ReadChangesRequest(station, 1, full: false), default);

        defined.Response.Should().NotBeNull(defined.Failure?.Message);
        first.Response.Should().BeOfType<ReadChangesResponse>().Which.Full.Should().BeTrue();
        var again = second.Response.Should().BeOfType<ReadChangesResponse>().Subject;
        again.Full.Should().Be(wholeListAgain, "without copy bytes the handler cannot compare, so it answers the whole list every time");
        again.Data.Length.Should().Be(wholeListAgain ? 8 : 0);
        again.Changes.Should().BeEmpty("the --no-process PLC's M bytes do not change");
        (await simulator.Exit).Should().Be(0);
    }

    [Theory]
    [InlineData("--plc-port", "1", "opanel: station 2: the handler cannot be generated: STL001: port 1 is not on the CPU 224; allowed: port 0")]
    [InlineData("--copy-bytes", "256", "opanel: --copy-bytes is a protocol 2 option; a protocol 3 handler has no reply delay")]
    [InlineData("--protocol", "4", "opanel: --protocol 4: the handler speaks protocol 3 (or the previous 2)")]
    [InlineData("--compact", "--protocol=2", "opanel: --compact is a protocol 3 handler: leave out --protocol 2")]
    [InlineData("--writable", "I,Q", "opanel: station 2: the handler cannot be generated: STL011")]
    [InlineData("--writable", "X", "opanel: --writable: 'X' is not an area; use a comma-separated list of Q, M, V, SM")]
    [InlineData("--buffer", "MB10", "opanel: --buffer MB10: give the handler's first V byte, e.g. VB1000")]
    [InlineData("--sbr", "64", "opanel: station 2: the handler cannot be generated: STL009")]
    [InlineData("--compact", "--allow-stop", "opanel: station 2: the handler cannot be generated: STL031: station 2 has --compact and --allow-stop, "
        + "but a compact handler has no STOP: it would be generated without the STOP that is allowed; leave out --compact for the full handler "
        + "with STOP, or leave out --allow-stop for the compact handler without it")]
    public void Simulate_ImpossibleHandlerOption_RefusedAsGenerateRefusesIt(string option, string value, string message)
    {
        var run = CliRunner.Run("simulate", "--cpu", "224", "--station", "2", "--device", "/dev/null", option, value);

        run.ExitCode.Should().Be(1);
        run.Error.Should().StartWith(message);
    }

    [Fact]
    public void SimulatePpi_HandlerOption_SaysPpiRunsNoHandler()
    {
        var run = CliRunner.Run("simulate", "--ppi", "--cpu", "224", "--station", "2", "--device", "/dev/null", "--copy-bytes", "0");

        run.ExitCode.Should().Be(1);
        run.Error.Should().Be("opanel: --ppi runs no handler: leave out --copy-bytes" + Environment.NewLine);
    }

    [Fact]
    public async Task Stop_CpuOtherThanTheStationReports_NothingSentAndExitOne()
    {
        using var pty = await SocatPtyPair.StartAsync();
        var simulator = await StartAsync(pty, "--cpu", "224", "--allow-stop");
        string[] line = ["--station", "2", "--device", pty.PathB, "--scan-ms", "1000"];

        var wrong = CliRunner.Run(["stop", "--yes", "--cpu", "226", .. line]);
        var still = CliRunner.Run(["read", "VB0", .. line]);

        wrong.ExitCode.Should().Be(1, wrong.Error);
        wrong.Out.Should().StartWith("station 2: STOP not sent: it is not the CPU 226 expected there (the PLC reports SMB6 16#20 (CPU 224 or CPU 224XP), CPU 226 has 16#90; the handler was generated for CPU 224, not CPU 226: regenerate it)");
        still.ExitCode.Should().Be(0, "the station still runs and answers: {0}", still.Error);
        (await simulator.Exit).Should().Be(0);
    }

    [Fact]
    public async Task Read_StationRunsAProtocol2Handler_SaysRegenerate()
    {
        using var pty = await SocatPtyPair.StartAsync();
        var simulator = await StartAsync(pty, "--cpu", "224", "--protocol", "2");

        // The default scan allowance: the READ's tries and the probe after them end well within the simulator's 4 s.
        var read = CliRunner.Run(["read", "VB100", "--station", "2", "--device", pty.PathB]);

        read.ExitCode.Should().Be(2);
        read.Error.Should().Contain("station 2 runs an Operator Panel handler of protocol v2, but the panel speaks protocol v3: regenerate the PLC code");
        (await simulator.Exit).Should().Be(0);
    }

    private static async Task<Simulation> StartAsync(SocatPtyPair pty, params string[] options)
    {
        var output = new StringWriter();
        var synchronized = TextWriter.Synchronized(output);
        string[] args = ["simulate", "--station", "2", "--device", pty.PathA, "--duration", "4", "--no-process", "--log-dir", LogDir, .. options];
        var simulation = new Simulation(Task.Run(() => OpanelApp.Run(args, synchronized, TextWriter.Null)), synchronized, output);
        var watch = Stopwatch.StartNew();
        while (!simulation.Text.Contains("simulating", StringComparison.Ordinal))
        {
            // Process start-up only: the one place real waiting is allowed, bounded by StartLimit.
            watch.Elapsed.Should().BeLessThan(StartLimit, $"the simulator should have started: {simulation.Text}");
            simulation.Exit.IsCompleted.Should().BeFalse($"the simulator stopped: {simulation.Text}");
            await Task.Delay(20);
        }

        return simulation;
    }

    private static string LogDir => Path.Combine(Path.GetTempPath(), "opanel-tests-logs");

    private sealed record Simulation(Task<int> Exit, TextWriter Synchronized, StringWriter Inner)
    {
        public string Text
        {
            get
            {
                // TextWriter.Synchronized locks the wrapper itself; read under the same lock.
                lock (Synchronized)
                {
                    return Inner.ToString();
                }
            }
        }
    }
}
