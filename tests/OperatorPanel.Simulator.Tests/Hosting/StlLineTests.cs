using OperatorPanel.Core.Protocol;
using OperatorPanel.Simulator.Reference;
using OperatorPanel.Simulator.Stl.Freeport;
using static OperatorPanel.Simulator.Tests.Hosting.StlStations;

namespace OperatorPanel.Simulator.Tests.Hosting;

public sealed class StlLineTests
{
    private static readonly TimeSpan CharacterTime = LineSettings.Default.CharacterTime;
    private static readonly TimeSpan ReplyDelay = TimeSpan.FromMilliseconds(5);

    /// <summary>Long enough for the v2 handler's scans (CRC of request and reply, a slice per scan) and the reply.</summary>
    private static readonly TimeSpan Serve = TimeSpan.FromMilliseconds(400);

    [Fact]
    public void StlLine_Read_ReplyLeavesAfterReplyDelayInTwoChunksCharacterByCharacter()
    {
        var line = Line(runProcess: false, 2);
        line.Stations[0].Memory.V.AsSpan(100, 4).SetBytes([0x12, 0x34, 0x56, 0x78]);
        var request = Read(2, ProtocolArea.V, 100, 4);
        var requestEnd = line.Now + (CharacterTime * request.Length);

        var reply = Exchange(line, request, Serve);

        Data(reply).Should().Equal(0x12, 0x34, 0x56, 0x78);
        var first = reply[0].At - requestEnd;
        // OP_PANEL checks the request (CRC) and builds the reply over several scans before the reply delay starts, after
        // the first pass of the reply's check. 26 characters: 10 pairs of body characters, two passes, two chunks; the
        // second leaves from the transmit-complete routine, a little after the first chunk's last character.
        first.Should().BeGreaterThan(ReplyDelay + CharacterTime + TimeSpan.FromMilliseconds(20)).And.BeLessThan(ReplyDelay + CharacterTime + TimeSpan.FromMilliseconds(80));
        var gaps = reply.Zip(reply.Skip(1), (a, b) => b.At - a.At).ToList();
        gaps.Where(gap => (gap - CharacterTime).Duration() > TimeSpan.FromTicks(1)).Should().ContainSingle()
            .Which.Should().BeGreaterThan(CharacterTime).And.BeLessThan(CharacterTime + TimeSpan.FromMilliseconds(10));
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

        var reply = Exchange(line, request, Serve);

        reply.Select(c => c.Value).Should().Equal(reference.HandleFrame(request));
    }

    [Fact]
    public void StlLine_WriteThenRead_ReadsTheWrittenBytesBack()
    {
        var line = Line(runProcess: false, 2);

        var written = Exchange(line, Write(2, ProtocolArea.V, 200, [0xCA, 0xFE], sequence: 3), Serve);
        var read = Exchange(line, Read(2, ProtocolArea.V, 200, 2, sequence: 4), Serve);

        Data(written).Should().Equal(0xCA, 0xFE);
        Data(read).Should().Equal(0xCA, 0xFE);
        line.Stations[0].Memory.V.AsSpan(200, 2).ToArray().Should().Equal(0xCA, 0xFE);
    }

    [Fact]
    public void StlLine_TwoStations_OnlyTheAddressedOneAnswers()
    {
        var line = Line(runProcess: false, 2, 3);

        var toThree = Exchange(line, Identify(3), Serve);
        var toTwo = Exchange(line, Identify(2), Serve);
        var toNine = Exchange(line, Identify(9), Serve);

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

        var inTerm = Exchange(line, Identify(2), Serve);
        line.Stations[0].Plc.ModeSwitch = ModeSwitch.Run;
        line.RunUntil(line.Now + TimeSpan.FromMilliseconds(20));
        var backInRun = Exchange(line, Identify(2), Serve);

        inTerm.Should().BeEmpty();
        line.Stations[0].Port.IsFreeport.Should().BeTrue();
        Decode(backInRun).Station.Should().Be(2);
    }

    [Fact]
    public void StlLine_Stop_StationIsSilent()
    {
        var line = Line(runProcess: false, 2);
        line.Stations[0].Plc.Stop();

        var reply = Exchange(line, Identify(2), Serve);

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
        var reply = Exchange(line, Read(2, ProtocolArea.Q, 0, 2), Serve);
        var after = station.Memory.Q.Take(2).ToArray();

        line.Processes.Should().ContainSingle().Which.Elapsed.Should().BeGreaterThan(TimeSpan.FromSeconds(2.9));
        station.Plc.InputImage.Should().Equal(station.Memory.I);
        after.Should().NotEqual(new byte[2]);

        // The reply shows Q as it was when OP_PANEL built it, some scans into the exchange: every bit that stayed the
        // same over the exchange must be in the reply as it is in Q.
        var payload = Data(reply);
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

        Exchange(line, Write(2, ProtocolArea.Q, 0, [value]), Serve);
        line.RunUntil(line.Now + TimeSpan.FromMilliseconds(200));

        station.IsOwnedByPanel(0, 0).Should().BeTrue();
        (station.Memory.Q[0] & 0x01).Should().Be(value & 0x01);
    }
}
