namespace OperatorPanel.Simulator.Tests.Stl.Corpus;

/// <summary>RealMath.awl and MulDiv.awl: IEEE single arithmetic, MUL/DIV with remainder, SM1.x and ENO.</summary>
public sealed class MathCorpusTests
{
    [Theory]
    [InlineData("VD0:real", 12.5)]
    [InlineData("VD4:real", 7.5)]
    [InlineData("VD8:real", 25.0)]
    [InlineData("VD12:real", 2.5)]
    [InlineData("VD16:real", 4.0)]
    [InlineData("VD20:real", 0.0)]
    [InlineData("VD24:real", 2.7182817)]
    [InlineData("VD28:real", 1.0)]
    [InlineData("VD32:real", 1.0)]
    [InlineData("VD36:real", 1.0)]
    public void RealArithmetic_GivesIeeeSingleResults(string address, double expected) =>
        CorpusProgram.Run("RealMath.awl", 0.05).Value(address).Should().BeApproximately(expected, 1e-6);

    [Fact]
    public void RealDivideByZero_SetsSm13LeavesOutAndEnoZero()
    {
        var run = CorpusProgram.Run("RealMath.awl", 0.05);

        run.Value("VD40:real").Should().Be(5.0);
        ((int)run.Value("VB60") & 0x08).Should().Be(0x08);
        run.Value("M0.2").Should().Be(0, "AENO after the failed /R");
        run.Value("M0.4").Should().Be(1, "AENO after the good /R");
        run.Value("VD44:real").Should().Be(2.5);
        ((int)run.Value("VB61") & 0x02).Should().Be(0x02, "SQRT of a negative real is illegal: SM1.1");
    }

    [Theory]
    [InlineData("Q0.0", 1)]
    [InlineData("Q0.1", 1)]
    [InlineData("Q0.2", 0)]
    [InlineData("Q0.3", 1)]
    [InlineData("Q0.4", 0)]
    public void RealCompares_CompareTheReals(string output, int expected) =>
        CorpusProgram.Run("RealMath.awl", 0.05).Value(output).Should().Be(expected);

    [Fact]
    public void Mul_SixteenBySixteenIntoThirtyTwoBits() =>
        CorpusProgram.Run("MulDiv.awl", 0.05).Value("VD0").Should().Be(120000);

    [Fact]
    public void Div_RemainderHighQuotientLow()
    {
        var run = CorpusProgram.Run("MulDiv.awl", 0.05);

        (run.Value("VW4"), run.Value("VW6")).Should().Be((2, 3));
        (run.Value("VW8"), run.Value("VW10")).Should().Be((-1, -3));
        run.Value("VD12").Should().Be(77, "division by zero leaves OUT");
        ((int)run.Value("VB30") & 0x08).Should().Be(0x08);
    }

    [Fact]
    public void MultiplyOverflow_SetsSm11AndEnoZero()
    {
        var run = CorpusProgram.Run("MulDiv.awl", 0.05);

        ((int)run.Value("VB31") & 0x02).Should().Be(0x02);
        run.Value("M0.1").Should().Be(0);
        run.Value("M0.2").Should().Be(1);
        run.Value("VW22").Should().Be(900);
    }
}
