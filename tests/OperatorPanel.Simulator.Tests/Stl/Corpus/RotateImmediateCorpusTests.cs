namespace OperatorPanel.Simulator.Tests.Stl.Corpus;

/// <summary>RotatesMoves.awl and Immediate.awl.</summary>
public sealed class RotateImmediateCorpusTests
{
    [Theory]
    [InlineData("VB0", 0x03)]
    [InlineData("VB10", 0x02)]
    [InlineData("VB1", 0xC0)]
    [InlineData("VB11", 0x02)]
    [InlineData("VW2", 0x0018)]
    [InlineData("VB12", 0x00)]
    [InlineData("VW4", unchecked((short)0x8000))]
    [InlineData("VB13", 0x02)]
    [InlineData("VD20", 0x34567812)]
    [InlineData("VD24", unchecked((int)0x81234567))]
    [InlineData("VB15", 0x01)]
    public void Rotates_ValueAndLastBitInSm11(string address, int expected) =>
        CorpusProgram.Run("RotatesMoves.awl", 0.05).Value(address).Should().Be(expected);

    [Fact]
    public void MovrAndBmd_MoveRealAndDoubleWords()
    {
        var run = CorpusProgram.Run("RotatesMoves.awl", 0.05);

        run.Value("VD40:real").Should().Be(3.5);
        new[] { run.Value("VD200"), run.Value("VD204"), run.Value("VD208") }.Should().Equal(0x11111111, 0x22222222, 0x33333333);
    }

    [Theory]
    [InlineData("Q0.0", 1)]
    [InlineData("Q0.1", 1)]
    [InlineData("Q0.2", 1)]
    [InlineData("Q0.3", 1)]
    [InlineData("Q0.4", 1)]
    [InlineData("Q0.5", 0)]
    [InlineData("Q1.0", 1)]
    [InlineData("Q1.2", 1)]
    [InlineData("Q1.3", 1)]
    [InlineData("VB0", 0b1101)]
    [InlineData("QB2", 0x5A)]
    public void ImmediateIo_ReadsInputsWritesOutputs(string address, int expected) =>
        CorpusProgram.Run("Immediate.awl", 0.05, "I0.0=1", "I0.2=1", "I0.3=1", "VB1=16#5A").Value(address).Should().Be(expected);

    [Fact]
    public void ImmediateOutput_ReachesTheFieldBeforeTheScanEnds()
    {
        var run = CorpusProgram.Run("Immediate.awl", 0.05, "I0.3=1", "VB1=16#5A");

        (run.Plc.OutputImage[1] & 0x0D).Should().Be(0x0D, "=I Q1.0 and SI Q1.2, 2 wrote the physical outputs");
        run.Plc.OutputImage[2].Should().Be(0x5A);
    }

    [Fact]
    public void ImmediateReset_ClearsOutputAndImage()
    {
        var run = CorpusProgram.Run("Immediate.awl", 0.05, "I0.3=1", "I0.4=1");

        run.Value("Q1.2").Should().Be(0);
        run.Value("Q1.3").Should().Be(1);
    }
}
