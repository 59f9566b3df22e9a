using OperatorPanel.Simulator.Reference;

namespace OperatorPanel.Simulator.Tests.Stl.Corpus;

/// <summary>Scr.awl, Clock.awl and StopWdr.awl: sequence control relays, the real-time clock, STOP and WDR.</summary>
public sealed class ControlCorpusTests
{
    [Fact]
    public void Scr_FirstStep_RedLightOnly()
    {
        var run = CorpusProgram.Run("Scr.awl", 1);

        (run.Value("S0.1"), run.Value("S0.2"), run.Value("Q0.4"), run.Value("Q0.2")).Should().Be((1, 0, 1, 0));
    }

    [Fact]
    public void Scr_AfterTwoSeconds_TransitionsToStepTwo()
    {
        var run = CorpusProgram.Run("Scr.awl", 2.5);

        (run.Value("S0.1"), run.Value("S0.2"), run.Value("Q0.4"), run.Value("Q0.2")).Should().Be((0, 1, 0, 1));
    }

    [Fact]
    public void Scr_StepThree_CscreEndsTheSegmentEarly()
    {
        var held = CorpusProgram.Run("Scr.awl", 6, "I0.0=1");
        held.Value("S0.3").Should().Be(1);
        held.Value("Q0.2").Should().Be(0, "step 3's first network ran");
        held.Value("VW0").Should().Be(0, "CSCRE skipped the rest of the segment");

        CorpusProgram.Run("Scr.awl", 6).Value("VW0").Should().BePositive("without I0.0 the segment runs to SCRE");
    }

    [Fact]
    public void Clock_TodwThenTodr_ReadsTheWrittenTimePlusElapsed()
    {
        var run = CorpusProgram.Run("Clock.awl", 6.01, "I0.0=1@1s");

        run.Plc.Memory.V.AsSpan(10, 8).ToArray().Should().Equal(0x26, 0x11, 0x24, 0x10, 0x30, 0x05, 0x00, 0x03);
    }

    [Fact]
    public void Clock_NeverSet_StartsAtTheSimulatorsPowerUpDate()
    {
        var run = CorpusProgram.Run("Clock.awl", 2.01);

        // 2000-01-01 00:00:02, a Saturday (7).
        run.Plc.Memory.V.AsSpan(10, 8).ToArray().Should().Equal(0x00, 0x01, 0x01, 0x00, 0x00, 0x02, 0x00, 0x07);
    }

    [Fact]
    public void Watchdog_LongScanWithoutWdr_GoesToStop()
    {
        var run = CorpusProgram.Run("StopWdr.awl", 3, "I0.5=1");

        run.Plc.Mode.Should().Be(OperatingMode.Stop);
        run.Plc.Fault!.Code.Should().Be("Watchdog");
    }

    [Fact]
    public void Wdr_InTheLongLoop_KeepsTheCpuInRun()
    {
        var run = CorpusProgram.Run("StopWdr.awl", 3, "I0.6=1");

        run.Plc.Mode.Should().Be(OperatingMode.Run);
        run.Value("VD14").Should().BeGreaterThanOrEqualTo(20_000, "one whole scan of 200 x 100 passes ran through");
    }

    [Fact]
    public void Stop_FinishesTheScanThenStops()
    {
        var run = CorpusProgram.Run("StopWdr.awl", 1, "I0.7=1@0.5s");

        run.Plc.Mode.Should().Be(OperatingMode.Stop);
        run.Plc.Fault!.Code.Should().Be("Stop");
        var scans = run.Value("VD20");
        scans.Should().Be(run.Plc.Scans, "the network after STOP ran in the last scan too");
    }
}
