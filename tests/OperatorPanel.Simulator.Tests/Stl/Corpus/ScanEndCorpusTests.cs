namespace OperatorPanel.Simulator.Tests.Stl.Corpus;

/// <summary>
/// ScanEnd.awl: what a run shows is the state at the end of the last complete scan (A5E00066097-02 p. 4-22, Figure
/// 4-12: the outputs are written after the program), whatever --for falls on.
/// </summary>
public sealed class ScanEndCorpusTests
{
    public static TheoryData<double> Times => [0.0013, 0.0021, 0.05, 0.0503, 0.1, 0.2345, 1, 1.0007];

    [Theory]
    [MemberData(nameof(Times))]
    public void Run_AnyTime_ShowsTheEndOfAScan(double seconds)
    {
        var run = CorpusProgram.Run("ScanEnd.awl", seconds);

        run.Value("Q0.6").Should().Be(1, "the program sets Q0.6 again at the end of every scan");
        run.Value("QB0").Should().Be(0x40);
        run.Value("VW2").Should().Be(10, "the FOR loop ran its 10 passes");
        run.Value("VW0").Should().Be(11, "NEXT leaves INDX past FINAL");
        run.Value("VD4").Should().Be(run.Plc.Scans, "every scan counted completed");
        run.ReadAt.Should().BeLessThanOrEqualTo(TimeSpan.FromSeconds(seconds));
    }

    [Fact]
    public void Run_ShorterThanTheFirstScan_SaysNoScanCompleted()
    {
        var run = CorpusProgram.Run("ScanEnd.awl", 0.0001);

        run.NoScanCompleted.Should().BeTrue();
    }
}
