namespace OperatorPanel.Simulator.Tests.Stl.Corpus;

/// <summary>ShiftRegister.awl: the SHRB example of System Manual ML801761 (manualslib 801761 p. 196, printed p. 182) (V100 0101 -> 1011 overflow 0 -> 0110 overflow 1).</summary>
public sealed class ShiftRegisterCorpusTests
{
    private static readonly string[] ManualSequence =
        ["VB100=2#0101", "I0.3=1", "I0.2=1@0.1s", "I0.2=0@0.2s", "I0.3=0@0.3s", "I0.2=1@0.4s"];

    [Fact]
    public void Shrb_FirstShift_MatchesTheManualsTimingDiagram()
    {
        var run = CorpusProgram.Run("ShiftRegister.awl", 0.25, ManualSequence);

        run.Value("VB100").Should().Be(0b1011);
        run.Value("M0.1").Should().Be(0, "the bit shifted out of V100.3 was 0");
    }

    [Fact]
    public void Shrb_SecondShift_MatchesTheManualsTimingDiagram()
    {
        var run = CorpusProgram.Run("ShiftRegister.awl", 0.5, ManualSequence);

        run.Value("VB100").Should().Be(0b0110);
        run.Value("M0.1").Should().Be(1, "the bit shifted out of V100.3 was 1");
    }

    [Fact]
    public void Shrb_NegativeLength_ShiftsIntoTheMostSignificantBitAndOutOfSBit()
    {
        var run = CorpusProgram.Run("ShiftRegister.awl", 0.2, "VB33=16#30", "I0.5=1", "I0.4=1@0.1s");

        run.Value("VB33").Should().Be(0x10, "V33.5 (1) moved down to V33.4 and V33.6 (0) to V33.5; bits 0-3 are outside the register");
        run.Value("VB35").Should().Be(0x02, "DATA entered the MSB V35.1");
        ((int)run.Value("VB40") & 0x02).Should().Be(0x02, "the S_BIT V33.4 (1) went to SM1.1");
    }
}
