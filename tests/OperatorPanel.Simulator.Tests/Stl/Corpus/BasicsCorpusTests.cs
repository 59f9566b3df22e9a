namespace OperatorPanel.Simulator.Tests.Stl.Corpus;

/// <summary>Basics.awl: the bit logic, move, integer, logic, shift, compare, ASCII and program control instructions.</summary>
public sealed class BasicsCorpusTests
{
    [Theory]
    [InlineData("VW40", 515)]
    [InlineData("VD42", 74998)]
    [InlineData("VB46", 0)]
    [InlineData("VB47", 255)]
    [InlineData("VD48", 1)]
    [InlineData("VW52", -1)]
    [InlineData("VW54", 0x12)]
    [InlineData("VB56", 200)]
    [InlineData("VD58", -5)]
    [InlineData("VW62", -300)]
    [InlineData("VB64", 0x31)]
    [InlineData("VW66", unchecked((short)0xF00F))]
    [InlineData("VD68", 0x0FFFFF0F)]
    [InlineData("VB72", 0x02)]
    [InlineData("VB73", 0x40)]
    [InlineData("VW74", 0x0004)]
    [InlineData("VW76", 0x2000)]
    [InlineData("VD78", 0x00000010)]
    [InlineData("VD82", 0x08000000)]
    [InlineData("VW100", 55)]
    [InlineData("VW104", 0)]
    public void FirstScanValues_AreTheInstructionsResults(string address, int expected) =>
        CorpusProgram.Run("Basics.awl", 0.05).Value(address).Should().Be(expected);

    [Fact]
    public void Moves_CopyBytesWordsAndSwap()
    {
        var v = CorpusProgram.Run("Basics.awl", 0.05).Plc.Memory.V;

        v.AsSpan(20, 8).ToArray().Should().Equal(0x12, 0x00, 0x34, 0x56, 0x78, 0x9A, 0xBC, 0xDE);
        v.AsSpan(30, 4).ToArray().Should().Equal(0x56, 0x34, 0x78, 0x9A);
        v.AsSpan(94, 6).ToArray().Should().Equal(0x3E, 0x1A, (byte)'3', (byte)'E', (byte)'1', (byte)'A');
    }

    [Theory]
    [InlineData("Q1.0", 1)]
    [InlineData("Q1.1", 1)]
    [InlineData("Q1.2", 0)]
    [InlineData("Q1.3", 1)]
    public void Compares_UnsignedBytesSignedWords(string output, int expected) =>
        CorpusProgram.Run("Basics.awl", 0.05).Value(output).Should().Be(expected);

    [Theory]
    [InlineData("I0.0=1", "I0.1=1", 1, 1, 0, 1)]
    [InlineData("I0.2=1", "I0.3=0", 1, 1, 0, 0)]
    [InlineData("I0.4=0", "I0.5=1", 0, 0, 1, 0)]
    public void BitLogic_StackOperations(string a, string b, int q0, int q1, int q2, int q3)
    {
        var run = CorpusProgram.Run("Basics.awl", 0.05, a, b);

        new[] { run.Value("Q0.0"), run.Value("Q0.1"), run.Value("Q0.2"), run.Value("Q0.3") }.Should().Equal(q0, q1, q2, q3);
    }

    [Theory]
    [InlineData("I0.0=1", 1)]
    [InlineData("I0.1=1", 0)]
    [InlineData("I0.2=1", 0)]
    public void Lds_CopiesTheNthStackLevelToTheTop(string input, int expected) =>
        CorpusProgram.Run("Basics.awl", 0.05, input).Value("Q1.4").Should().Be(expected);

    [Fact]
    public void Edges_CountRisingAndFallingOnce()
    {
        var run = CorpusProgram.Run("Basics.awl", 1, CorpusProgram.Pulses("I0.6", 0.1, 0.3, 0.5));

        (run.Value("VB0"), run.Value("VB1")).Should().Be((3, 3));
    }

    [Fact]
    public void SetReset_SeveralBits()
    {
        CorpusProgram.Run("Basics.awl", 0.05, "I0.7=1").Value("MB1").Should().Be(0b111);
        CorpusProgram.Run("Basics.awl", 0.1, "I0.7=1", "I0.7=0@0.05s").Value("MB1").Should().Be(0b101);
    }

    [Fact]
    public void CallCretAndTimedInterrupt_RunBesideTheMainProgram()
    {
        var run = CorpusProgram.Run("Basics.awl", 1);

        run.Value("VW120").Should().BeInRange(19, 20, "event 11 every 50 ms for 1 s");
        run.Value("VW112").Should().Be(Math.Min(run.Value("VW110"), 999), "CRET returns before the second INCW from call 1000 on");
    }

    [Fact]
    public void Dtch_StopsTheTimedInterrupt()
    {
        var run = CorpusProgram.Run("Basics.awl", 1, "I1.0=1@0.5s");

        run.Value("VW120").Should().BeInRange(9, 10);
    }

    [Fact]
    public void Disi_HoldsTheTimedInterrupts()
    {
        var run = CorpusProgram.Run("Basics.awl", 1, "I1.1=1@0.5s");

        run.Value("VW120").Should().BeInRange(9, 10, "ENI in the first scan, DISI from 0.5 s on (ENI is not executed again)");
    }
}
