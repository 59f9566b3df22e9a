using OperatorPanel.Simulator.Stl;
using OperatorPanel.Simulator.Stl.Run;

namespace OperatorPanel.Simulator.Tests.Stl.Corpus;

/// <summary>
/// TimerOnDelay.awl (the TON example of ML801761, manualslib 801761 p. 212, printed 198), TimerRetentive, TimerOffDelay and TimerOneShot.awl against the timer rules (ML801761 p. 211-212;
/// C79000-G7076-C233-01 p. 9-16 Table 9-1 resolutions, p. 9-17 Table 9-2 timer actions).
/// </summary>
public sealed class TimerCorpusTests
{
    [Theory]
    [InlineData(0.99, 9, 0)]
    [InlineData(1.01, 10, 1)]
    [InlineData(5.0, 49, 1)]
    public void Ton100ms_InputOn_BitAtPresetAndValueCountsOn(double seconds, int value, int bit)
    {
        var run = CorpusProgram.Run("TimerOnDelay.awl", seconds, "I0.0=1");

        run.Value("T37").Should().Be(value);
        run.Value("T37.bit").Should().Be(bit);
        run.Value("Q0.0").Should().Be(bit, "LD T37 reads the timer bit");
        run.Value("VW0").Should().Be(value, "MOVW T37 reads the current value");
    }

    [Fact]
    public void Ton_InputOff_ClearsBitAndValue()
    {
        var run = CorpusProgram.Run("TimerOnDelay.awl", 2.5, "I0.0=1", "I0.0=0@2s");

        run.Value("T37").Should().Be(0);
        run.Value("Q0.0").Should().Be(0);
        run.Value("T32").Should().Be(0);
    }

    [Theory]
    [InlineData(0.025, 0)]
    [InlineData(0.045, 1)]
    public void Ton10ms_UpdatedAtScanStart_BitAfter30ms(double seconds, int bit) =>
        CorpusProgram.Run("TimerOnDelay.awl", seconds, "I0.0=1").Value("T33.bit").Should().Be(bit);

    [Theory]
    [InlineData(0.499, 0)]
    [InlineData(0.502, 1)]
    public void Ton1ms_CountsEveryMillisecond_BitAfter500ms(double seconds, int bit)
    {
        var run = CorpusProgram.Run("TimerOnDelay.awl", seconds, "I0.0=1");

        run.Value("T32.bit").Should().Be(bit);
        run.Value("T32").Should().BeInRange((seconds * 1000) - 2, seconds * 1000);
    }

    [Fact]
    public void Ton_LongOn_StopsAt32767()
    {
        var run = CorpusProgram.Run("TimerOnDelay.awl", 40, "I0.0=1");

        run.Value("T32").Should().Be(32767, "a 1 ms timer reaches its maximum after 32.767 s");
        run.Value("T37").Should().Be(399);
    }

    [Fact]
    public void TimerCompare_CurrentValue_ReadAsWord() =>
        CorpusProgram.Run("TimerOnDelay.awl", 0.55, "I0.0=1").Value("Q0.3").Should().Be(1, "LDW>= T37, +5 after 0.5 s");

    [Fact]
    public void Tonr_InputOffThenOn_AccumulatesAndKeepsBitUntilReset()
    {
        string[] inputs = ["I0.1=1", "I0.1=0@1s", "I0.1=1@2s", "I0.1=0@4s"];

        CorpusProgram.Run("TimerRetentive.awl", 1.5, inputs).Value("T5").Should().Be(10, "held while IN is off");
        var beforePreset = CorpusProgram.Run("TimerRetentive.awl", 2.95, inputs);
        beforePreset.Value("T5").Should().Be(19);
        beforePreset.Value("Q0.0").Should().Be(0);
        var afterPreset = CorpusProgram.Run("TimerRetentive.awl", 3.2, inputs);
        afterPreset.Value("T5").Should().Be(21);
        afterPreset.Value("Q0.0").Should().Be(1);
        var off = CorpusProgram.Run("TimerRetentive.awl", 6, inputs);
        off.Value("T5").Should().Be(30, "1 s + 2 s on");
        off.Value("Q0.0").Should().Be(1, "a TONR keeps its bit with IN off");
        off.Value("Q0.1").Should().Be(1, "the 10 ms TONR T1 passed 1.5 s too");
    }

    [Fact]
    public void Tonr_Reset_ClearsBitAndValue()
    {
        var run = CorpusProgram.Run("TimerRetentive.awl", 6, "I0.1=1", "I0.1=0@4s", "I0.2=1@5s");

        run.Value("T5").Should().Be(0);
        run.Value("Q0.0").Should().Be(0);
        run.Value("T1").Should().Be(0);
    }

    [Fact]
    public void Tof_NoOnToOffTransition_NeverTimesOrTurnsOn()
    {
        var run = CorpusProgram.Run("TimerOffDelay.awl", 3);

        run.Value("T38.bit").Should().Be(0);
        run.Value("T38").Should().Be(0);
    }

    [Theory]
    [InlineData(1.5, 1, 0)]
    [InlineData(3.9, 1, 18)]
    [InlineData(4.1, 0, 20)]
    [InlineData(9.0, 0, 20)]
    public void Tof_InputOffAfterOn_BitOffAtPresetAndValueStops(double seconds, int bit, int value)
    {
        var run = CorpusProgram.Run("TimerOffDelay.awl", seconds, "I0.0=1@1s", "I0.0=0@2s");

        run.Value("Q0.0").Should().Be(bit);
        run.Value("T38").Should().Be(value);
    }

    [Fact]
    public void Tof_InputBackOnBeforePreset_BitStaysOnAndValueCleared()
    {
        var run = CorpusProgram.Run("TimerOffDelay.awl", 3.5, "I0.0=1@1s", "I0.0=0@2s", "I0.0=1@3s");

        run.Value("Q0.0").Should().Be(1);
        run.Value("T38").Should().Be(0);
        run.Value("Q0.1").Should().Be(1, "the 10 ms TOF T34 as well");
    }

    [Fact]
    public void SelfResettingTimers_BehaveAsFigure94Shows()
    {
        var run = CorpusProgram.Run("TimerOneShot.awl", 2);

        run.Value("VW0").Should().Be(0, "10 ms: the box resets the bit before LD T33 reads it (C233-01 p. 9-19)");
        run.Value("VW2").Should().Be(6, "100 ms: one scan at each preset of 300 ms");
        run.Value("VW6").Should().Be(6, "10 ms reset by Q0.3: one scan each 300 ms");
    }

    [Fact]
    public void TwentyTimers_ScanTakesThePublishedTimerTime()
    {
        var run = new StlRun(CorpusProgram.Load("TimerScanTime.awl"));
        var scans = new List<StlScan>();
        run.Plc.ScanCompleted += (_, scan) => scans.Add(scan);
        run.Run(TimeSpan.FromSeconds(2.5), [Setting("I0.0=1")]);

        // C233-01 Tables A-2..A-4: timer/counter 50-64 us, the high end taken; LD and = 0.37 us; 250 us housekeeping.
        scans.Should().AllSatisfy(s => s.Busy.Should().Be(TimeSpan.FromTicks(((20 * (370 + 64_000)) + (2 * 370) + 250_000) / 100)));
        run.Value("SMW22").Should().Be(1, "1.54 ms: the scan time in ms (the 400 us these timers took before made 8 ms)");
        run.Value("Q0.0").Should().Be(1, "T56 reached its 2 s");
    }

    private static StlSetting Setting(string text) =>
        StlSetting.TryParse(text, CorpusProgram.Cpu224, out var setting, out var error) ? setting : throw new ArgumentException(error);
}
