using System.Text;
using OperatorPanel.Simulator.Soak;

namespace OperatorPanel.Simulator.Tests.Soak;

public sealed class FaultInjectorTests
{
    private static readonly byte[] Frames = Encoding.ASCII.GetBytes(string.Concat(Enumerable.Repeat("<0201030400000A>", 2000)));

    [Fact]
    public void Pass_SameSeed_GivesTheSameFaults()
    {
        var first = new FaultInjector(LineFaults.Mixed, 7).Pass(Frames);
        var second = new FaultInjector(LineFaults.Mixed, 7).Pass(Frames);
        var other = new FaultInjector(LineFaults.Mixed, 8).Pass(Frames);

        second.Should().Equal(first);
        other.Should().NotEqual(first);
    }

    [Fact]
    public void Pass_CleanLine_ChangesNothing()
    {
        new FaultInjector(LineFaults.Clean, 1).Pass(Frames).Should().Equal(Frames);
    }

    [Fact]
    public void Pass_OnePercentFlips_FlipsAboutOneBitInHundredAndDropsNothing()
    {
        var injector = new FaultInjector(LineFaults.Flips, 3);

        var received = injector.Pass(Frames);

        received.Should().HaveCount(Frames.Length);
        var flipped = received.Zip(Frames, (a, b) => System.Numerics.BitOperations.PopCount((uint)(a ^ b))).Sum();
        flipped.Should().Be((int)injector.BitsFlipped);
        ((double)flipped / (8 * Frames.Length)).Should().BeApproximately(0.01, 0.001);
    }

    [Fact]
    public void Pass_EveryFrameDropped_LeavesOnlyWhatIsBetweenFrames()
    {
        var injector = new FaultInjector(new LineFaults("all frames", 0, 0, 1), 1);

        var received = injector.Pass(Encoding.ASCII.GetBytes("x<0201>y<0301>z"));

        Encoding.ASCII.GetString(received).Should().Be("xyz");
        injector.FramesDropped.Should().Be(2);
    }

    [Fact]
    public void Pass_MixedProfile_DropsCharactersAndFramesNearTheirRates()
    {
        var injector = new FaultInjector(LineFaults.Mixed, 5);

        injector.Pass(Frames);

        ((double)injector.FramesDropped / 2000).Should().BeApproximately(0.05, 0.015);
        ((double)injector.CharactersDropped / Frames.Length).Should().BeApproximately(0.005 * 0.95, 0.0015);
    }
}
