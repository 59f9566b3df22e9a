using System.Text;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Transport;
using OperatorPanel.Simulator.Hosting;
using OperatorPanel.Simulator.Reference;
using OperatorPanel.Simulator.Stl.Freeport;
using OperatorPanel.Simulator.Stl.Ppi;
using OperatorPanel.TestKit;
using OperatorPanel.ViewModels.Tests.Fakes;
using OperatorPanel.ViewModels.Wizard;

namespace OperatorPanel.ViewModels.Tests.Wizard;

public sealed class LinkStepViewModelTests
{
    private const string Where = "Station 2 on COM3 at 9600 8N1";
    private readonly FakeConnectionTester _tester = new();

    [Fact]
    public void Ports_PresentOnes_AreListedWithTheFtdiModuleMarked()
    {
        var link = Wizard().LinkStep;

        link.Ports.Select(p => p.Label).Should().Equal("COM3", "COM7 - FTDI USB serial (radio module or USB cable)");
        link.IsFtdiPort.Should().BeFalse();
        link.PortName = "COM7";
        link.IsFtdiPort.Should().BeTrue();
    }

    [Fact]
    public void BaudRate_NotAFreeportRateOfTheCpu_IsRefused()
    {
        var wizard = Wizard();
        wizard.CpuStep.Cpu = CpuProfiles.For(CpuModel.Cpu224, CpuRevision.Early);
        wizard.CurrentIndex = 4;

        wizard.LinkStep.BaudRate = 115200;

        wizard.FinishCommand.CanExecute(null).Should().BeFalse();
        wizard.Message.Should().Be("CPU 224 (early) cannot run Freeport at 115200 baud; use one of 300, 600, 1200, 2400, 4800, 9600, 19200, 38400.");
        wizard.LinkStep.BaudRates.Should().Equal(300, 600, 1200, 2400, 4800, 9600, 19200, 38400);
    }

    [Fact]
    public async Task TestConnection_MatchingHandler_ShowsTheAnswerAsSuccess()
    {
        var link = Wizard().LinkStep;
        _tester.Reply = Identify(CpuModel.Cpu224, smb6: 0x20);

        await link.TestConnectionCommand.ExecuteAsync(null);

        link.TestSucceeded.Should().BeTrue();
        link.TestResult.Should().Be($"{Where} answered: handler for CPU 224, protocol 2, handler revision 1, mode switch RUN, last scan 3 ms. Matches CPU 224.");
        _tester.Asked.Should().ContainSingle().Which.Should().Be((new SerialSettings { PortName = "COM3" }, new Station(2)));
    }

    [Fact]
    public async Task TestConnection_HandlerForAnotherCpu_ShowsTheMismatch()
    {
        var link = Wizard().LinkStep;
        _tester.Reply = Identify(CpuModel.Cpu226, smb6: 0x90);

        await link.TestConnectionCommand.ExecuteAsync(null);

        link.TestSucceeded.Should().BeFalse();
        link.TestResult.Should().EndWith("CPU mismatch with CPU 224: the PLC reports SMB6 16#90 (CPU 226), CPU 224 has 16#20; "
            + "the handler was generated for CPU 226, not CPU 224: regenerate it.");
    }

    [Fact]
    public async Task TestConnection_NoAnswer_ShowsWhatToCheck()
    {
        var link = Wizard().LinkStep;
        _tester.Failure = new PlcCommunicationException(PlcErrorKind.NoAnswer, new Station(2), "no valid reply to Identify after 2 attempts");

        await link.TestConnectionCommand.ExecuteAsync(null);

        link.TestSucceeded.Should().BeFalse();
        link.TestResult.Should().Be($"{Where}: no answer. Check the cable or radio module, the station address, that the PLC is in RUN with its "
            + "mode switch at RUN (not TERM) and that the handler is loaded. (no valid reply to Identify after 2 attempts)");
    }

    [Fact]
    public async Task TestConnection_SimulatedPlc_IdentifiesItOverARealLink()
    {
        var clock = new ManualTimeProvider();
        var plc = new Simulator.Reference.V3.ReferenceHandler(new Simulator.Reference.V3.HandlerSetup(new Station(2), CpuProfiles.For(CpuModel.Cpu224)));
        var link = Wizard(new LinkConnectionTester(_ => new ReferencePlcTransport(plc), clock)).LinkStep;

        await link.TestConnectionCommand.ExecuteAsync(null);

        link.TestResult.Should().StartWith($"{Where} answered: handler for CPU 224, protocol 3").And.EndWith("Matches CPU 224.");
        link.TestSucceeded.Should().BeTrue();
    }

    [Fact]
    public async Task TestConnection_RealLinkTimesOut_ShowsNoAnswer()
    {
        var clock = new ManualTimeProvider();
        var (request, v2) = (V3Identify(), Encoding.ASCII.GetString(RequestCodec.Encode(new IdentifyRequest(new Station(2), 1))));
        var transport = new ScriptedTransport($"""
            > {request}   // IDENTIFY v3 station 2, SEQ 1
            < no response
            > {request}   // the cable's one retry: the identical frame
            < no response
            > 3E          // a lone '>' ends a receive an older handler opened on our bytes
            > "{v2}"      // one v2 IDENTIFY: is an older handler there?
            < no response
            > 3E
            > "<02010102>"   // one v1 IDENTIFY (XOR check), SEQ 1
            < no response
            """, clock, "COM3");
        var link = Wizard(new LinkConnectionTester(_ => transport, clock)).LinkStep;

        await RunOnTheClockAsync(link.TestConnectionCommand.ExecuteAsync(null), clock);
        link.TestSucceeded.Should().BeFalse();
        link.TestResult.Should().StartWith($"{Where}: no answer.").And.Contain("no valid reply to v3 Identify after 2 attempts");
        transport.AssertComplete();
    }

    [Fact]
    public async Task TestConnection_StationRunsAV1Handler_SaysRegenerateThePlcCode()
    {
        var clock = new ManualTimeProvider();
        var (request, v2) = (V3Identify(), Encoding.ASCII.GetString(RequestCodec.Encode(new IdentifyRequest(new Station(2), 1))));
        var v1Reply = Encoding.ASCII.GetString(Core.Protocol.V1.V1IdentifyProbe.Frame(
            [0x02, 0x01, 0x81, 0x00, 0x01, 0x01, 0x03, 0x01, 0x0E, 0x77, 0x05, 0x20, 0x01, 0x00, 0x05, 0x00, 0x03, 0x00, 0x09]));
        var transport = new ScriptedTransport($"""
            > {request}   // IDENTIFY v3 station 2: a v1 handler ignores it
            < no response
            > {request}
            < no response
            > 3E
            > "{v2}"      // a v2 IDENTIFY: a v1 handler ignores it too
            < no response
            > 3E
            > "<02010102>"   // the v1 IDENTIFY probe, SEQ 1
            < "{v1Reply}"    // answered: PROTOCOL_VERSION 01
            """, clock, "COM3");
        var link = Wizard(new LinkConnectionTester(_ => transport, clock)).LinkStep;

        await RunOnTheClockAsync(link.TestConnectionCommand.ExecuteAsync(null), clock);
        link.TestSucceeded.Should().BeFalse();
        link.TestResult.Should().Be($"{Where}: station 2 runs an Operator Panel handler of protocol v1, but the panel speaks protocol v3: regenerate the PLC code (opanel generate) and download it.");
        transport.AssertComplete();
    }

    [Fact]
    public async Task TestConnection_PortHangs_EndsByItselfAfterTheLinksLongestTest()
    {
        var clock = new ManualTimeProvider();
        var link = new ProjectWizardViewModel(_tester, new FakePortCatalog(), clock).LinkStep;
        _tester.Hangs = true;
        var longest = LinkConnectionTester.LongestTest(new SerialSettings { PortName = "COM3" }, new Station(2));

        var test = link.TestConnectionCommand.ExecuteAsync(null);
        link.TestResult.Should().Be($"{Where}: asking... (at most {Math.Ceiling(longest.TotalSeconds):0} s)");
        clock.Advance(longest - TimeSpan.FromMilliseconds(1));
        test.IsCompleted.Should().BeFalse();
        clock.Advance(TimeSpan.FromMilliseconds(1));
        await test.Guarded();

        link.TestSucceeded.Should().BeFalse();
        link.TestResult.Should().StartWith($"{Where}: nothing came back within {Math.Ceiling(longest.TotalSeconds):0} s, longer than the link itself waits");
        _tester.ToldToStop.Should().BeTrue();
        longest.Should().BeLessThan(TimeSpan.FromSeconds(5), "9600 baud over a cable: two seconds to open the port and four IDENTIFY attempts");
    }

    [Fact]
    public async Task TestConnection_Cancelled_EndsAtOnceAndSaysSo()
    {
        var wizard = Wizard();
        var link = wizard.LinkStep;
        _tester.Hangs = true;

        var test = link.TestConnectionCommand.ExecuteAsync(null);
        link.TestConnectionCancelCommand.CanExecute(null).Should().BeTrue("Stop test is offered while the test runs");
        wizard.Close();
        await test.Guarded();

        link.TestResult.Should().Be($"{Where}: test cancelled.");
        link.TestSucceeded.Should().BeNull();
        _tester.ToldToStop.Should().BeTrue();
        link.TestConnectionCommand.IsRunning.Should().BeFalse();
    }

    [Fact]
    public void Protocol_Ppi_SetsPpisCharacterAndRatesAndRefusesTheRadio()
    {
        var wizard = Wizard();
        wizard.CurrentIndex = 4;
        var link = wizard.LinkStep;

        link.Protocol = LinkProtocol.Ppi;

        (link.Parity, link.DataBits, link.Kind, link.BaudRate).Should().Be((Parity.Even, 8, LinkKind.Cable, 9600));
        link.BaudRates.Should().Equal(9600, 19200, 187500);
        link.Build().Protocol.Should().Be(LinkProtocol.Ppi);
        wizard.FinishCommand.CanExecute(null).Should().BeTrue();
        link.Kind = LinkKind.RadioModule;
        wizard.Message.Should().Be("The radio modules carry the handler's Freeport frames; PPI needs the cable.");
        LinkStepViewModel.ProtocolHint.Should().StartWith("Freeport needs our handler in the PLC");
    }

    [Fact]
    public async Task TestConnection_Ppi_ReadsTheSimulatedCpuWithoutHandler()
    {
        var line = new StlLine(new LineSettings(9600, Parity.Even, 8));
        StlStation.TryCreate(EmptyProgram.Awl, CpuProfiles.For(CpuModel.Cpu224), 0, new LineSettings(9600, Parity.Even, 8), out var station, out var error).Should().BeTrue(error);
        station!.AttachPpi(new PpiSettings(2, 9600));
        line.Attach(station, runProcess: false);
        line.RunUntil(TimeSpan.FromMilliseconds(50));
        var transport = new SimulatedLineTransport(line);
        var link = Wizard(new LinkConnectionTester(_ => transport, transport.Clock)).LinkStep;
        link.Protocol = LinkProtocol.Ppi;

        await link.TestConnectionCommand.ExecuteAsync(null);

        link.TestResult.Should().StartWith("Station 2 on COM3 at 9600 8E1 answered over PPI (no handler needed): SMB6 16#20, mode switch RUN")
            .And.Contain("RUN or STOP is not known over PPI").And.EndWith("Matches CPU 224.");
        link.TestSucceeded.Should().BeTrue();
    }

    private ProjectWizardViewModel Wizard(IConnectionTester? tester = null) => new(tester ?? _tester, new FakePortCatalog());

    private static IdentifyResponse Identify(CpuModel model, byte smb6) =>
        new(new Station(2), 1, HandlerIdentity.ProtocolVersion, 1, HandlerIdentity.CpuModelCode(model), 1, 0x3C, HandlerIdentity.MaxReadData, 5, smb6, 0x01, 3, 2, 9, 0, 7764, 428, 0, 120);

    /// <summary>
    /// Advances the manual clock in 5 ms steps, only while the link waits on a timer (the gap before a frame), until
    /// the test connection ends. The scripted transport moves the clock itself for a read that gets nothing, so a
    /// reply waiting in it is always read before its time-out: advancing while the link was between its write and
    /// its read let a busy machine push the clock past the v1 probe's reply time first ("no answer" instead of the
    /// v1 message, seen once in a full run). A fixed number of steps hung instead (3 minutes); the wall-clock guard
    /// fails the test.
    /// </summary>
    private static async Task RunOnTheClockAsync(Task test, ManualTimeProvider clock)
    {
        var guard = System.Diagnostics.Stopwatch.StartNew();
        while (!test.IsCompleted && guard.Elapsed < TimeSpan.FromSeconds(30))
        {
            if (clock.ActiveTimers > 0)
            {
                clock.Advance(TimeSpan.FromMilliseconds(5));
            }

            await Task.Yield();
        }

        await test.WaitAsync(TimeSpan.FromSeconds(5));
    }

    /// <summary>IDENTIFY v3 to station 2 under the link's first SEQ (1), as hex pairs for the script.</summary>
    private static string V3Identify() =>
        string.Join(' ', Core.Protocol.V3.Codec.Encode(Core.Protocol.V3.Request.Identify(new Station(2), 1)).Select(b => b.ToString("X2", System.Globalization.CultureInfo.InvariantCulture)));
}
