using System.Text;

namespace OperatorPanel.Simulator.Tests.Stl.Corpus;

/// <summary>Conversions.awl: SEG (the manual's example, 05 -> 2#0110_1101), DECO/ENCO, BCD, real to integer, ITA/DTA/RTA.</summary>
public sealed class ConversionCorpusTests
{
    [Theory]
    [InlineData(5, 0x6D)]
    [InlineData(0, 0x3F)]
    [InlineData(9, 0x67)]
    [InlineData(0x0F, 0x71)]
    public void Seg_Digit_LightsTheManualsSegments(int digit, int segments) =>
        CorpusProgram.Run("Conversions.awl", 0.05, $"VB48={digit}").Value("AC1").Should().Be(segments);

    [Fact]
    public void DecoEnco_BitNumberAndBack()
    {
        var run = CorpusProgram.Run("Conversions.awl", 0.05, "VB60=3", "VW64=16#0140");

        run.Value("VW62").Should().Be(8);
        run.Value("VB66").Should().Be(6, "the lowest set bit of 16#0140");
    }

    [Fact]
    public void BcdConversions_BothWays_AndInvalidSetsSm16()
    {
        var run = CorpusProgram.Run("Conversions.awl", 0.05);

        run.Value("VW70").Should().Be(1234);
        run.Value("VW72").Should().Be(0x1234);
        run.Value("VW74").Should().Be(12345, "IBCD of a value above 9999 leaves the word");
        ((int)run.Value("VB76") & 0x40).Should().Be(0x40, "SM1.6: invalid BCD");
    }

    [Fact]
    public void Aeno_AfterGoodAndBadBox_FollowsEno()
    {
        var run = CorpusProgram.Run("Conversions.awl", 0.05);

        run.Value("M0.5").Should().Be(1);
        run.Value("M0.4").Should().Be(0);
    }

    [Fact]
    public void RealToInteger_RoundsHalfAwayFromZeroAndTruncates()
    {
        var run = CorpusProgram.Run("Conversions.awl", 0.05);

        run.Value("VD84:real").Should().Be(1234567);
        new[] { run.Value("VD88"), run.Value("VD92"), run.Value("VD96"), run.Value("VD100") }.Should().Equal(3, -3, 2, -2);
        run.Value("VD104").Should().Be(77, "a real beyond a double integer leaves OUT");
        ((int)run.Value("VB108") & 0x02).Should().Be(0x02, "SM1.1");
    }

    [Fact]
    public void ToAscii_RightJustifiedWithDecimalsAndSeparator()
    {
        var v = CorpusProgram.Run("Conversions.awl", 0.05).Plc.Memory.V;

        Encoding.ASCII.GetString(v, 110, 8).Should().Be(" 123.45 ".Trim().PadLeft(8));
        Encoding.ASCII.GetString(v, 120, 8).Should().Be("  -0,012");
        Encoding.ASCII.GetString(v, 130, 12).Should().Be("   -123.4567");
        Encoding.ASCII.GetString(v, 150, 10).Should().Be("  1234.567");
    }
}
