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
    public void Bus_LongReplyOfOneStation_ClearsTheListsOfAnotherLikeTheStlHandler()
    {
        var bus = new BusSimulator();
        var two = bus.Attach(Plc(2));
        bus.Attach(Plc(3));
        // Station 2 stores one list of 2 items (tail 8 bytes: floor 248), then station 3 answers a 116-byte READ:
        // 18 + 232 = 250 characters reach station 2's buffer past its floor.
        var define = new DefineListRequest(new Station(2), 1, 1, [new ReadItem(ProtocolArea.V, 0, 1), new ReadItem(ProtocolArea.V, 10, 1)]);
        Encoding.ASCII.GetString(bus.Feed(RequestCodec.Encode(define)).Single()).Should().StartWith("<02018500");

        var replies = bus.Feed(RequestCodec.Encode(new ReadRequest(new Station(3), 2, [new ReadItem(ProtocolArea.V, 0, 116)])));

        replies.Should().ContainSingle().Which.Length.Should().Be(250);
        two.ReceivedFrames.Should().Be(3, "its DEFINE LIST, the READ for station 3 and station 3's reply");
        var read = bus.Feed(RequestCodec.Encode(new ReadListRequest(new Station(2), 3, 1)));
        Encoding.ASCII.GetString(read.Single()).Should().StartWith("<02038607", "the list was cleared: 07");
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
        bus.Ports.Select(p => p.ReceivedFrames).Should().Equal([2, 1], "station 1 received the request and station 2's reply");
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
