using System.Text;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Simulator.Reference;

namespace OperatorPanel.Simulator.Tests.Reference;

public sealed class SimulatedPlcPortTests
{
    private static ReferencePlc Plc(int station) => new(new HandlerConfig(new Station(station), CpuProfiles.For(CpuModel.Cpu224)));

    [Fact]
    public void Feed_FrameInPiecesAfterNoise_RepliesOnceAtTheEndCharacter()
    {
        var port = new SimulatedPlcPort(Plc(1));

        port.Feed("\0\u0001>"u8).Should().BeEmpty();
        port.Feed("<0107"u8).Should().BeEmpty();
        var replies = port.Feed("01dl`l>"u8);

        replies.Should().ContainSingle();
        Encoding.ASCII.GetString(replies[0]).Should().StartWith("<01078100");
        port.ReplyDelay.Should().Be(TimeSpan.FromMilliseconds(5));
    }

    [Fact]
    public void Feed_255CharactersWithoutEnd_DropsTheReceiveAndRestarts()
    {
        var port = new SimulatedPlcPort(Plc(1));

        port.Feed(Encoding.ASCII.GetBytes("<" + new string('0', 254))).Should().BeEmpty();
        port.Feed("<010701dl`l>"u8).Should().ContainSingle();
        port.DroppedReceives.Should().Be(1);
    }

    [Fact]
    public void Feed_StartCharacterInsideMessage_IsStoredLikeRcvAndTheHandlerAnswersTheFrameFromTheLastStart()
    {
        var port = new SimulatedPlcPort(Plc(1));

        var replies = port.Feed("<01<010701dl`l>"u8);

        port.ReceivedFrames.Should().Be(1);
        replies.Should().ContainSingle();
        Encoding.ASCII.GetString(replies[0]).Should().StartWith("<01078100C0C4");
    }

    [Fact]
    public void Bus_TwoStations_OnlyTheAddressedOneAnswers()
    {
        var bus = new BusSimulator();
        bus.Attach(Plc(1));
        bus.Attach(Plc(2));

        var replies = bus.Feed(RequestCodec.Encode(new IdentifyRequest(new Station(2), 7)));

        replies.Should().ContainSingle();
        Encoding.ASCII.GetString(replies[0]).Should().StartWith("<020781");
        bus.Ports.Should().OnlyContain(p => p.ReceivedFrames == 1);
    }

    [Fact]
    public void Bus_ReplyOfOneStation_IsIgnoredByTheOthers()
    {
        var bus = new BusSimulator();
        bus.Attach(Plc(1));
        bus.Attach(Plc(2));
        var reply = bus.Feed("<010701dl`l>"u8).Single();

        bus.Feed(reply).Should().BeEmpty();
    }
}
