namespace OperatorPanel.Simulator.Tests.Stl.Corpus;

/// <summary>Counters.awl against the manual's counter rules (C79000-G7076-C233-01 p. 9-24; A5E00307987-04 CTUD example with C48, PV 4).</summary>
public sealed class CounterCorpusTests
{
    [Fact]
    public void Ctud_FiveUpTwoDown_BitFollowsCurrentAtLeastPreset()
    {
        string[] ups = CorpusProgram.Pulses("I4.0", 0.1, 0.2, 0.3, 0.4, 0.5);
        string[] downs = CorpusProgram.Pulses("I3.0", 0.7, 0.8);

        var atFour = CorpusProgram.Run("Counters.awl", 0.45, [.. ups, .. downs]);
        atFour.Value("C48").Should().Be(4);
        atFour.Value("Q0.0").Should().Be(1, "current 4 >= PV 4");
        var atFive = CorpusProgram.Run("Counters.awl", 0.6, [.. ups, .. downs]);
        atFive.Value("C48").Should().Be(5);
        var afterDowns = CorpusProgram.Run("Counters.awl", 0.9, [.. ups, .. downs]);
        afterDowns.Value("C48").Should().Be(3);
        afterDowns.Value("Q0.0").Should().Be(0, "current 3 < PV 4");
        afterDowns.Value("VW0").Should().Be(3, "MOVW C48 reads the current value");
    }

    [Fact]
    public void Ctud_Reset_ClearsValueAndBit()
    {
        var run = CorpusProgram.Run("Counters.awl", 1, [.. CorpusProgram.Pulses("I4.0", 0.1, 0.2, 0.3, 0.4), "I2.0=1@0.6s"]);

        run.Value("C48").Should().Be(0);
        run.Value("C48.bit").Should().Be(0);
    }

    [Fact]
    public void Ctud_DownFromZero_GoesNegative()
    {
        var run = CorpusProgram.Run("Counters.awl", 1, CorpusProgram.Pulses("I3.0", 0.1, 0.2));

        run.Value("C48").Should().Be(-2, "CTUD counts below zero (it wraps only at -32768)");
    }

    [Fact]
    public void Ctu_CountsRisingEdgesOnly_BitAtPresetAndResetByInput()
    {
        var held = CorpusProgram.Run("Counters.awl", 1, "I0.0=1");
        held.Value("C1").Should().Be(1, "an input held on is one rising edge");

        var counted = CorpusProgram.Run("Counters.awl", 1, CorpusProgram.Pulses("I0.0", 0.1, 0.2, 0.3, 0.4));
        counted.Value("C1").Should().Be(4);
        counted.Value("Q0.1").Should().Be(1);
        counted.Value("Q0.3").Should().Be(1, "LDW>= C1, +2");

        var reset = CorpusProgram.Run("Counters.awl", 1, [.. CorpusProgram.Pulses("I0.0", 0.1, 0.2, 0.3), "I0.1=1@0.5s"]);
        reset.Value("C1").Should().Be(0);
        reset.Value("Q0.1").Should().Be(0);
    }

    [Fact]
    public void RInstruction_OnCounter_ClearsValueAndBit()
    {
        var run = CorpusProgram.Run("Counters.awl", 1, [.. CorpusProgram.Pulses("I0.0", 0.1, 0.2, 0.3), "I0.4=1@0.5s"]);

        run.Value("C1").Should().Be(0);
        run.Value("C1.bit").Should().Be(0);
    }

    [Fact]
    public void Ctd_LoadThenCountDown_StopsAtZeroWithBitOn()
    {
        string[] inputs = ["I0.3=1@0.05s", "I0.3=0@0.1s", .. CorpusProgram.Pulses("I0.2", 0.2, 0.3, 0.4)];

        var loaded = CorpusProgram.Run("Counters.awl", 0.15, inputs);
        loaded.Value("C2").Should().Be(2);
        loaded.Value("Q0.2").Should().Be(0, "LD clears the bit");
        var one = CorpusProgram.Run("Counters.awl", 0.28, inputs);
        one.Value("C2").Should().Be(1);
        var done = CorpusProgram.Run("Counters.awl", 1, inputs);
        done.Value("C2").Should().Be(0, "CTD stops at 0");
        done.Value("Q0.2").Should().Be(1);
    }
}
