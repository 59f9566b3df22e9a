using OperatorPanel.Core.Protocol;
using OperatorPanel.Simulator.Reference;
using OperatorPanel.Simulator.Stl.Freeport;
using static OperatorPanel.Simulator.Tests.Hosting.StlStations;

namespace OperatorPanel.Simulator.Tests.Hosting;

public sealed class StlLineTests
{
    private static readonly TimeSpan CharacterTime = LineSettings.Default.CharacterTime;
    private static readonly TimeSpan ReplyDelay = TimeSpan.FromMilliseconds(5);

    [Fact]
    public void StlLine_Read_ReplyLeavesAfterReplyDelayCharacterByCharacter()
    {
        var line = Line(runProcess: false, 2);
        line.Stations[0].Memory.V.AsSpan(100, 4).SetBytes([0x12, 0x34, 0x56, 0x78]);
        var request = Read(2, ProtocolArea.V, 100, 4);
        var requestEnd = line.Now + (CharacterTime * request.Length);

        var reply = Exchange(line, request, TimeSpan.FromMilliseconds(100));

        Decode(reply).Payload.Should().Equal(0x00, 0x12, 0x34, 0x56, 0x78);
        var first = reply[0].At - requestEnd;
        // OP_PANEL checks the request and builds the reply over a few scans (about 14 ms for this READ at the manual's
        // execution times) before the reply delay starts.
        first.Should().BeGreaterThan(ReplyDelay + CharacterTime + TimeSpan.FromMilliseconds(5)).And.BeLessThan(ReplyDelay + CharacterTime + TimeSpan.FromMilliseconds(30));
        reply.Zip(reply.Skip(1), (a, b) => b.At - a.At).Should().OnlyContain(gap => (gap - CharacterTime).Duration() <= TimeSpan.FromTicks(1));
        line.Replies.Should().Be(1);
        line.FramesReceived.Should().Be(1);
    }

    [Fact]
    public void StlLine_Read_AnswersAsTheReferenceModelDoes()
    {
        var line = Line(runProcess: false, 2);
        var reference = new ReferencePlc(new HandlerConfig(new Core.Addressing.Station(2), Cpu224));
        line.Stations[0].Memory.M.AsSpan(0, 8).SetBytes([1, 2, 3, 4, 5, 6, 7, 8]);
        reference.Memory.M.AsSpan(0, 8).SetBytes([1, 2, 3, 4, 5, 6, 7, 8]);
        var request = Read(2, ProtocolArea.M, 2, 5, sequence: 9);

        var reply = Exchange(line, request, TimeSpan.FromMilliseconds(100));

        reply.Select(c => c.Value).Should().Equal(reference.HandleFrame(request));
    }

    [Fact]
    public void StlLine_WriteThenRead_ReadsTheWrittenBytesBack()
    {
        var line = Line(runProcess: false, 2);

        var written = Exchange(line, Write(2, ProtocolArea.V, 200, [0xCA, 0xFE], sequence: 3), TimeSpan.FromMilliseconds(100));
        var read = Exchange(line, Read(2, ProtocolArea.V, 200, 2, sequence: 4), TimeSpan.FromMilliseconds(100));

        Decode(written).Payload.Should().Equal(0x00, 0xCA, 0xFE);
        Decode(read).Payload.Should().Equal(0x00, 0xCA, 0xFE);
        line.Stations[0].Memory.V.AsSpan(200, 2).ToArray().Should().Equal(0xCA, 0xFE);
    }

    [Fact]
    public void StlLine_TwoStations_OnlyTheAddressedOneAnswers()
    {
        var line = Line(runProcess: false, 2, 3);

        var toThree = Exchange(line, Identify(3), TimeSpan.FromMilliseconds(100));
        var toTwo = Exchange(line, Identify(2), TimeSpan.FromMilliseconds(100));
        var toNine = Exchange(line, Identify(9), TimeSpan.FromMilliseconds(100));

        Decode(toThree).Station.Should().Be(3);
        Decode(toTwo).Station.Should().Be(2);
        toNine.Should().BeEmpty();
        line.Replies.Should().Be(2);
    }

    [Fact]
    public void StlLine_ModeSwitchTerm_StationFallsSilentAndAnswersAgainAtRun()
    {
        var line = Line(runProcess: false, 2);
        line.Stations[0].Plc.ModeSwitch = ModeSwitch.Term;
        line.RunUntil(line.Now + TimeSpan.FromMilliseconds(20));

        var inTerm = Exchange(line, Identify(2), TimeSpan.FromMilliseconds(100));
        line.Stations[0].Plc.ModeSwitch = ModeSwitch.Run;
        line.RunUntil(line.Now + TimeSpan.FromMilliseconds(20));
        var backInRun = Exchange(line, Identify(2), TimeSpan.FromMilliseconds(100));

        inTerm.Should().BeEmpty();
        line.Stations[0].Port.IsFreeport.Should().BeTrue();
        Decode(backInRun).Station.Should().Be(2);
    }

    [Fact]
    public void StlLine_Stop_StationIsSilent()
    {
        var line = Line(runProcess: false, 2);
        line.Stations[0].Plc.Stop();

        var reply = Exchange(line, Identify(2), TimeSpan.FromMilliseconds(100));

        reply.Should().BeEmpty();
        line.Stations[0].Port.IsFreeport.Should().BeFalse();
    }

    [Fact]
    public void StlLine_DemoProcess_DrivesTheStationAndItsRepliesShowIt()
    {
        var line = Line(runProcess: true, 2);
        line.RunUntil(TimeSpan.FromSeconds(3));
        var station = line.Stations[0];

        var before = station.Memory.Q.Take(2).ToArray();
        var reply = Exchange(line, Read(2, ProtocolArea.Q, 0, 2), TimeSpan.FromMilliseconds(100));
        var after = station.Memory.Q.Take(2).ToArray();

        line.Processes.Should().ContainSingle().Which.Elapsed.Should().BeGreaterThan(TimeSpan.FromSeconds(2.9));
        station.Plc.InputImage.Should().Equal(station.Memory.I);
        after.Should().NotEqual(new byte[2]);

        // The reply shows Q as it was when OP_PANEL built it, some scans into the exchange: every bit that stayed the
        // same over the exchange must be in the reply as it is in Q.
        var payload = Decode(reply).Payload.Skip(1).ToArray();
        for (var i = 0; i < 2; i++)
        {
            var stable = (byte)~(before[i] ^ after[i]);
            (payload[i] & stable).Should().Be(after[i] & stable);
        }
    }

    [Fact]
    public void StlLine_PanelWritesOutput_DemoProgramLeavesItAlone()
    {
        var line = Line(runProcess: true, 2);
        line.RunUntil(TimeSpan.FromSeconds(1));
        var station = line.Stations[0];
        var value = (byte)(station.Memory.Q[0] ^ 0x01);

        Exchange(line, Write(2, ProtocolArea.Q, 0, [value]), TimeSpan.FromMilliseconds(200));
        line.RunUntil(line.Now + TimeSpan.FromMilliseconds(200));

        station.IsOwnedByPanel(0, 0).Should().BeTrue();
        (station.Memory.Q[0] & 0x01).Should().Be(value & 0x01);
    }
}
