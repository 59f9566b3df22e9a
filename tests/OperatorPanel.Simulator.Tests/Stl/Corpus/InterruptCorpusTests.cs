using OperatorPanel.Simulator.Stl;

namespace OperatorPanel.Simulator.Tests.Stl.Corpus;

/// <summary>
/// EdgeInterrupts.awl and HighSpeedCounter.awl: input edge interrupts from changes of I0.0-I0.3 (events 0-7, ML801761
/// p. 172, Table 6-50), and events and instructions the simulator cannot produce, warned about rather than refused.
/// </summary>
public sealed class InterruptCorpusTests
{
    [Fact]
    public void EdgeInterrupts_EachRisingAndFallingEdgeOfI00_RunsItsRoutineOnce()
    {
        var run = CorpusProgram.Run("EdgeInterrupts.awl", 1, CorpusProgram.Pulses("I0.0", 0.1, 0.3, 0.5));

        run.Value("VW0").Should().Be(3, "three rising edges, event 0");
        run.Value("VW2").Should().Be(3, "three falling edges, event 1");
    }

    [Fact]
    public void EdgeInterrupts_PulseShorterThanAScan_CaughtByTheInterruptNotByTheScan()
    {
        // A 0.1 ms pulse on I0.1, well inside one scan: the scan's LD I0.1 / EU never sees it, its edge interrupt does.
        var run = CorpusProgram.Run("EdgeInterrupts.awl", 0.5, "I0.1=1@200.05ms", "I0.1=0@200.15ms");

        run.Value("VW4").Should().Be(1);
        run.Value("VW10").Should().Be(0);
    }

    [Fact]
    public void EdgeInterrupts_DetachedEvent_NoLongerRunsItsRoutine()
    {
        string[] settings = [.. CorpusProgram.Pulses("I0.3", 0.1, 0.2), "I0.4=1@0.3s", .. CorpusProgram.Pulses("I0.3", 0.4, 0.5)];

        CorpusProgram.Run("EdgeInterrupts.awl", 1, settings).Value("VW6").Should().Be(2, "DTCH 6 at 0.3 s");
    }

    [Fact]
    public void EdgeInterrupts_InputAlreadyOnAtPowerUp_IsNoEdge()
    {
        CorpusProgram.Run("EdgeInterrupts.awl", 0.5, "I0.0=1").Value("VW0").Should().Be(0);
    }

    [Fact]
    public void HighSpeedCounter_RestOfTheProgram_RunsWithWarningsByLine()
    {
        var load = StlProgramLoader.Load(CorpusProgram.Text("HighSpeedCounter.awl"), CorpusProgram.Cpu224);

        load.Succeeded.Should().BeTrue();
        load.Warnings.Select(w => (w.Line, w.Message.Split(':')[0])).Should().Equal((8, "HDEF"), (9, "ATCH"), (11, "HSC"), (14, "PLS"));
        load.Warnings[1].Message.Should().Contain("event 12 (HSC0 CV=PV) never fires in the simulator");
        var run = CorpusProgram.Run("HighSpeedCounter.awl", 1.5, "I0.0=1", "I0.2=1");
        run.Value("Q0.1").Should().Be(1, "the on-delay of the rest of the program ran");
        run.Value("M0.0").Should().Be(0, "the CV=PV routine never ran");
    }

    [Fact]
    public void HighSpeedCounter_Strict_RefusedByNameAndLine()
    {
        var load = StlProgramLoader.Load(CorpusProgram.Text("HighSpeedCounter.awl"), CorpusProgram.Cpu224, new StlLoadOptions { Strict = true });

        load.Succeeded.Should().BeFalse();
        load.Diagnostics.Select(d => (d.Line, d.Message.Split(' ')[0])).Should().Equal((8, "HDEF"), (9, "ATCH:"), (11, "HSC"), (14, "PLS"));
    }
}
