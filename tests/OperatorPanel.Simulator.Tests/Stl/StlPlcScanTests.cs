using OperatorPanel.Core.Protocol;
using OperatorPanel.Simulator.Reference;
using OperatorPanel.Simulator.Stl;
using static OperatorPanel.Simulator.Tests.Stl.StlTestPrograms;

namespace OperatorPanel.Simulator.Tests.Stl;

public sealed class StlPlcScanTests
{
    [Fact]
    public void Scan_FirstScanBitAndModeSwitch_AreSeenByTheProgram()
    {
        var plc = Plc("LD     SM0.1\nINCB   VB0\nNetwork 2\nLD     SM0.7\n=      Q0.0\nNetwork 3\nLD     I0.1\n=      Q0.1");
        plc.InputImage[0] = 0b10;
        plc.RunUntil(TimeSpan.FromMilliseconds(10));
        plc.OutputImage[0].Should().Be(0b11);
        plc.ModeSwitch = ModeSwitch.Term;
        plc.RunUntil(TimeSpan.FromMilliseconds(20));

        plc.OutputImage[0].Should().Be(0b10);
        plc.Memory.V[0].Should().Be(1);
        plc.Scans.Should().BeGreaterThan(10);
    }

    [Fact]
    public void StopThenRun_ResetsPortsAndRunsAFirstScanAgain()
    {
        var plc = Plc("LD     SM0.1\nINCB   VB0");
        var port = new FakeStlPort(plc.Memory, () => plc.Now);
        plc.AttachPort(port);
        plc.RunUntil(TimeSpan.FromMilliseconds(5));
        plc.Stop();
        var scans = plc.Scans;
        plc.RunUntil(TimeSpan.FromMilliseconds(10));
        plc.Scans.Should().Be(scans);
        plc.Run();
        plc.RunUntil(TimeSpan.FromMilliseconds(15));

        (plc.Memory.V[0], port.Resets).Should().Be((2, 2));
    }

    [Fact]
    public void ScanTimes_AreReportedInSmw22To26()
    {
        // A 2-iteration loop of BMB over 100 bytes makes a scan of a few ms (17 us per byte, StlTiming.PerByte).
        var plc = Plc("LD     SM0.0\nFOR    VW0, 1, 2\nNetwork 2\nLD     SM0.0\nBMB    VB100, VB400, 100\nNetwork 3\nNEXT");
        plc.RunUntil(TimeSpan.FromMilliseconds(100));

        var last = plc.Memory.ReadWord(ProtocolArea.SM, 22);
        last.Should().BeInRange(1, 5);
        plc.Memory.ReadWord(ProtocolArea.SM, 24).Should().BeLessThanOrEqualTo(last);
        plc.Memory.ReadWord(ProtocolArea.SM, 26).Should().BeGreaterThanOrEqualTo(last);
    }

    [Fact]
    public void TimedInterrupt_FiresEveryIntervalFromAttach()
    {
        var plc = Plc("LD     SM0.1\nMOVB   10, SMB34\nATCH   TICK, 10\nENI", "INTERRUPT_BLOCK TICK:INT0\r\nBEGIN\r\nNetwork 1\r\nLD     SM0.0\r\nINCB   VB0\r\nEND_INTERRUPT_BLOCK\r\n");
        var runs = new List<StlInterruptRun>();
        plc.InterruptServed += (_, run) => runs.Add(run);
        plc.RunUntil(TimeSpan.FromMilliseconds(55));

        plc.Memory.V[0].Should().Be(5);
        runs.Select(r => Math.Round(r.RaisedAt.TotalMilliseconds)).Should().Equal(10, 20, 30, 40, 50);
        runs.Should().AllSatisfy(r => r.Instructions.Should().Be(2));
        runs.Should().AllSatisfy(r => (r.StartedAt - r.RaisedAt).Should().BeLessThan(TimeSpan.FromMilliseconds(0.1)));
    }

    [Fact]
    public void UserProgramTime_LengthensEveryScanAndServesInterruptsInIt()
    {
        // OB1 is two instructions (well under 0.1 ms); 7 ms of user program after it, then the 0.25 ms housekeeping.
        var plc = Plc("LD     SM0.1\nMOVB   2, SMB34\nATCH   TICK, 10\nENI", "INTERRUPT_BLOCK TICK:INT0\r\nBEGIN\r\nNetwork 1\r\nLD     SM0.0\r\nINCB   VB0\r\nEND_INTERRUPT_BLOCK\r\n");
        plc.UserProgramTime = TimeSpan.FromMilliseconds(7);
        var scans = new List<StlScan>();
        var runs = new List<StlInterruptRun>();
        plc.ScanCompleted += (_, scan) => scans.Add(scan);
        plc.InterruptServed += (_, run) => runs.Add(run);

        plc.RunUntil(TimeSpan.FromMilliseconds(100));

        scans.Should().NotBeEmpty().And.OnlyContain(s => s.EndedAt - s.StartedAt > TimeSpan.FromMilliseconds(7.25));
        runs.Should().HaveCountGreaterThan(40).And.OnlyContain(r => r.StartedAt - r.RaisedAt < TimeSpan.FromMilliseconds(0.1));
        runs.Should().Contain(r => r.InterruptedLine == 0, "most timed interrupts fall in the user's program, outside OB1's instructions");
        plc.Memory.ReadWord(ProtocolArea.SM, 22).Should().BeInRange(7, 8);
    }

    [Fact]
    public void InterruptedLine_TheMainProgramsNextInstruction()
    {
        // A 300-pass loop outlasts the 1 ms timed interrupt: the routine runs between two of the loop's instructions.
        const string body = "LD     SM0.1\nMOVB   1, SMB34\nATCH   TICK, 10\nENI\nNetwork 2\nLD     SM0.0\nFOR    VW0, 1, 300\n" +
            "Network 3\nLD     SM0.0\nINCD   AC0\nNetwork 4\nNEXT";
        const string tick = "INTERRUPT_BLOCK TICK:INT0\r\nBEGIN\r\nNetwork 1\r\nLD     SM0.0\r\nINCB   VB20\r\nEND_INTERRUPT_BLOCK\r\n";
        var plc = Plc(body, tick);
        var lines = Text(body, tick).Split('\n').Select(l => l.TrimEnd('\r')).ToList();
        var runs = new List<StlInterruptRun>();
        plc.InterruptServed += (_, run) => runs.Add(run);

        plc.RunUntil(TimeSpan.FromMilliseconds(20));

        var interrupted = runs.Select(r => r.InterruptedLine).Where(line => line > 0).Distinct().Select(line => lines[line - 1]).ToList();
        interrupted.Should().NotBeEmpty().And.BeSubsetOf(["LD     SM0.0", "INCD   AC0", "NEXT"]);
    }

    [Fact]
    public void TimedInterrupt_InTheMiddleOfTheMainProgram_LeavesItsAccumulatorsAsTheyWere()
    {
        // OB1 counts to 300 in AC0 with a loop that outlasts the 1 ms timed interrupt; the routine tramples AC0-AC3.
        var plc = Plc(
            "LD     SM0.1\nMOVB   1, SMB34\nATCH   TRAMPLE, 10\nENI\nNetwork 2\nLD     SM0.0\nMOVD   0, AC0\nFOR    VW0, 1, 300\n" +
            "Network 3\nLD     SM0.0\nINCD   AC0\nNetwork 4\nNEXT\nNetwork 5\nLD     SM0.0\nMOVD   AC0, VD10",
            "INTERRUPT_BLOCK TRAMPLE:INT0\r\nBEGIN\r\nNetwork 1\r\nLD     SM0.0\r\nMOVD   16#7777, AC0\r\nMOVD   16#7777, AC1\r\n" +
            "MOVD   16#7777, AC2\r\nMOVD   16#7777, AC3\r\nINCB   VB20\r\nEND_INTERRUPT_BLOCK\r\n");
        var interrupted = 0;
        plc.InterruptServed += (_, _) => interrupted++;

        plc.RunUntil(TimeSpan.FromMilliseconds(50));

        interrupted.Should().BeGreaterThan(10);
        plc.Memory.ReadDoubleWord(ProtocolArea.V, 10).Should().Be(300);
    }

    [Fact]
    public void DisabledInterrupts_AreQueuedUpToTheQueueDepthAndServedAfterEni()
    {
        var plc = Plc(
            "LD     SM0.1\nMOVB   4, SMB34\nATCH   TICK, 10\nNetwork 2\nLD     I0.0\nENI\nNetwork 3\nLDN    I0.0\nDISI",
            "INTERRUPT_BLOCK TICK:INT0\r\nBEGIN\r\nNetwork 1\r\nLD     SM0.0\r\nINCB   VB0\r\nMOVB   SMB4, VB1\r\nEND_INTERRUPT_BLOCK\r\n");
        // Ticks every 4 ms: 9 by 37 ms, one more than the queue holds; the 8 queued ones take about 1.2 ms to serve.
        plc.RunUntil(TimeSpan.FromMilliseconds(37));
        plc.Memory.V[0].Should().Be(0);
        plc.InputImage[0] = 1;
        plc.RunUntil(TimeSpan.FromMilliseconds(39.9));

        plc.Memory.V[0].Should().Be(8, "the timed queue holds 8 events");
        (plc.Memory.V[1] & 0x04).Should().Be(0x04, "SM4.2 reports the lost timed events");
    }

    [Fact]
    public void EchoProgram_AnswersEachMessageThroughTheFakePort()
    {
        const string echo =
            "LD     SM0.1\nATCH   RX_DONE, 23\nATCH   TX_DONE, 9\nENI\nRCV    VB100, 0";
        const string blocks =
            "INTERRUPT_BLOCK RX_DONE:INT0\r\nTITLE=Copy the message and send it back\r\nBEGIN\r\nNetwork 1\r\n" +
            "LD     SM0.0\r\nMOVB   VB100, VB200\r\nMOVD   &VB101, AC1\r\nMOVD   &VB201, AC2\r\nFOR    VW300, 1, VW96\r\n" +
            "Network 2\r\nLD     SM0.0\r\nMOVB   *AC1, *AC2\r\nINCD   AC1\r\nINCD   AC2\r\nNetwork 3\r\nNEXT\r\n" +
            "Network 4\r\nLD     SM0.0\r\nXMT    VB200, 0\r\nEND_INTERRUPT_BLOCK\r\n" +
            "INTERRUPT_BLOCK TX_DONE:INT1\r\nBEGIN\r\nNetwork 1\r\nLD     SM0.0\r\nRCV    VB100, 0\r\nEND_INTERRUPT_BLOCK\r\n";
        var plc = Plc(echo, blocks);
        var port = new FakeStlPort(plc.Memory, () => plc.Now);
        plc.AttachPort(port);
        var runs = new List<StlInterruptRun>();
        plc.InterruptServed += (_, run) => runs.Add(run);
        plc.Memory.V[97] = 3;
        port.Arrive(TimeSpan.FromMilliseconds(5), 0x3C, 0x41, 0x0D);
        port.Arrive(TimeSpan.FromMilliseconds(20), 0x3C, 0x42, 0x0D);
        plc.RunUntil(TimeSpan.FromMilliseconds(40));

        port.Sent.Should().HaveCount(2);
        port.Sent[0].Should().Equal(0x3C, 0x41, 0x0D);
        port.Sent[1].Should().Equal(0x3C, 0x42, 0x0D);
        runs.Select(r => r.Event).Should().Equal(23, 9, 23, 9);
        runs[0].Instructions.Should().Be(5 + (3 * 5) + 2, "FOR set-up, three iterations with NEXT, XMT");
        port.SentAt[0].Should().BeGreaterThan(TimeSpan.FromMilliseconds(7));
    }
}
