using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Protocol.V3;
using OperatorPanel.Simulator.Soak;

namespace OperatorPanel.Simulator.Tests.Soak;

public sealed class FaultInjectorTests
{
    /// <summary>A v3 WRITE of VW10 = 16#3C3E: its data bytes are '&lt;' and '&gt;', which must not start or end a frame.</summary>
    private static readonly byte[] Write = Codec.Encode(Request.Write(new Station(2), 1, ProtocolArea.V, 10, [0x3C, 0x3E]));

    private static readonly byte[] Frames = [.. Enumerable.Repeat(Write, 2000).SelectMany(f => f)];

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
    public void Pass_EveryFrameDropped_LeavesOnlyWhatIsBetweenFramesByTheirLen()
    {
        var injector = new FaultInjector(new LineFaults("all frames", 0, 0, 1), 1);

        var received = injector.Pass([(byte)'x', .. Write, (byte)'y', .. Write, (byte)'z']);

        received.Should().Equal((byte)'x', (byte)'y', (byte)'z');
        injector.FramesDropped.Should().Be(2);
    }

    [Fact]
    public void Pass_FrameArrivingInPieces_IsDroppedWholeAndTheNextByteKept()
    {
        var injector = new FaultInjector(new LineFaults("all frames", 0, 0, 1), 1);

        var received = new List<byte>();
        foreach (var piece in Write.Append((byte)'z').Chunk(3))
        {
            received.AddRange(injector.Pass(piece));
        }

        received.Should().Equal((byte)'z');
        injector.FramesDropped.Should().Be(1);
    }

    [Fact]
    public void Pass_StartCharacterWithImpossibleLen_IsNotFollowedAsAFrame()
    {
        var injector = new FaultInjector(new LineFaults("all frames", 0, 0, 1), 1);

        // LEN 2: no v3 frame is that short; followed, it would end the drop anywhere (or swallow the frame after it).
        var received = injector.Pass([(byte)'<', 0x02, (byte)'k', .. Write]);

        received.Should().Equal((byte)'k');
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
