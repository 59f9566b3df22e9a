using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Simulator.Reference;
using static OperatorPanel.Simulator.Tests.Reference.Exchange;

namespace OperatorPanel.Simulator.Tests.Reference;

/// <summary>08 READ CHANGES on the reference model: copies, pairs, FULL and its fallbacks (docs/protocol-v2.md, "08 READ CHANGES").</summary>
public sealed class ReferencePlcReadChangesTests
{
    /// <summary>VD100 (4 bytes) and MB2: D = 5.</summary>
    private const string TwoItems = "02 04006404 03000201";

    private static ReferencePlc Plc(int copyBytes = HandlerMemory.DefaultCopyBytes)
    {
        var plc = new ReferencePlc(new HandlerConfig(new Station(1), CpuProfiles.For(CpuModel.Cpu224), copyBytes: copyBytes));
        plc.Memory.WriteDoubleWord(ProtocolArea.V, 100, 1111);
        plc.Memory.M[2] = 0x05;
        Send(plc, "01 01 05", "01 " + TwoItems)!.Payload.Should().Equal(0x00);
        return plc;
    }

    private static byte[] Changes(ReferencePlc plc, bool full = false, int list = 1) =>
        [.. Send(plc, "01 20 08", $"{list:X2} {(full ? 1 : 0):X2}")!.Payload];

    [Fact]
    public void ReadChanges_FirstAfterDefine_AnswersFullBecauseTheCopyIsNotValidYet()
    {
        Changes(Plc()).Should().Equal(0x00, 0xFF, 0x00, 0x00, 0x04, 0x57, 0x05);
    }

    [Fact]
    public void ReadChanges_NothingChanged_AnswersNoPairs()
    {
        var plc = Plc();
        Changes(plc);

        Changes(plc).Should().Equal(0x00, 0x00);
    }

    [Fact]
    public void ReadChanges_OneByteChanged_AnswersItsIndexAndValueAndTheCopyMovesOn()
    {
        var plc = Plc();
        Changes(plc);
        plc.Memory.M[2] = 0x07;

        Changes(plc).Should().Equal(0x00, 0x01, 0x04, 0x07);
        Changes(plc).Should().Equal(0x00, 0x00);
    }

    [Fact]
    public void ReadChanges_TwoBytesChangedOfFive_AnswersPairsInAscendingIndexOrder()
    {
        var plc = Plc();
        Changes(plc);
        plc.Memory.M[2] = 0x00;
        plc.Memory.V[100] = 0x12;

        Changes(plc).Should().Equal(0x00, 0x02, 0x00, 0x12, 0x04, 0x00); // 2K = 4 < 5
    }

    [Fact]
    public void ReadChanges_PairsNotShorterThanTheData_FallsBackToFull()
    {
        var plc = Plc();
        Changes(plc);
        plc.Memory.WriteDoubleWord(ProtocolArea.V, 100, 70000); // 00 01 11 70: three bytes differ, 2K = 6 >= 5

        Changes(plc).Should().Equal(0x00, 0xFF, 0x00, 0x01, 0x11, 0x70, 0x05);
        Changes(plc).Should().Equal(0x00, 0x00);
    }

    [Fact]
    public void ReadChanges_FullFlag_AnswersTheWholeListEvenWhenNothingChanged()
    {
        var plc = Plc();
        Changes(plc);

        Changes(plc, full: true).Should().Equal(0x00, 0xFF, 0x00, 0x00, 0x04, 0x57, 0x05);
    }

    [Fact]
    public void ReadChanges_NoCopyBytes_AlwaysAnswersFull()
    {
        var plc = Plc(copyBytes: 0);
        Changes(plc);

        Changes(plc).Should().Equal(0x00, 0xFF, 0x00, 0x00, 0x04, 0x57, 0x05);
    }

    [Fact]
    public void ReadChanges_ListDefinedAfterTheCopiesRanOut_AlwaysAnswersFullWhileTheFirstKeepsItsCopy()
    {
        var plc = Plc(copyBytes: 7); // list 1 takes 5, list 2 needs 4
        Send(plc, "01 02 05", "02 01 04006404")!.Payload.Should().Equal(0x00);
        Changes(plc, list: 1);
        Changes(plc, list: 2);

        Changes(plc, list: 1).Should().Equal(0x00, 0x00);
        Changes(plc, list: 2).Should().Equal(0x00, 0xFF, 0x00, 0x00, 0x04, 0x57);
    }

    [Fact]
    public void ReadList_DoesNotTouchTheCopy()
    {
        var plc = Plc();
        Changes(plc);
        plc.Memory.M[2] = 0x07;

        Send(plc, "01 21 06", "01")!.Payload.Should().Equal(0x00, 0x00, 0x00, 0x04, 0x57, 0x07);

        Changes(plc).Should().Equal(0x00, 0x01, 0x04, 0x07);
    }

    [Fact]
    public void Invalidation_DropsTheCopies_SoTheRedefinedListAnswersFullFirst()
    {
        var plc = Plc();
        Changes(plc);

        // A WRITE of 114 bytes has 20 + 228 = 248 characters and reaches the floor at 248: every list is cleared.
        Send(plc, "01 22 03", "04 0400 72 " + new string('0', 228))!.Payload[0].Should().Be(0x00);
        Changes(plc).Should().Equal(0x07);
        Send(plc, "01 23 05", "01 " + TwoItems)!.Payload.Should().Equal(0x00);

        Changes(plc).Should().Equal(0x00, 0xFF, 0x00, 0x00, 0x04, 0x57, 0x05);
    }

    [Fact]
    public void ReplyLost_NextReadChangesWithoutFull_MissesTheChange_WhichIsWhyThePcMustAskFull()
    {
        var plc = Plc();
        Changes(plc);
        plc.Memory.M[2] = 0x07;
        Changes(plc).Should().Equal(0x00, 0x01, 0x04, 0x07); // this reply is lost on the line: the PC never sees 07

        Changes(plc).Should().Equal(new byte[] { 0x00, 0x00 }, "the copy moved on with the lost reply");
        Changes(plc, full: true).Should().Equal(0x00, 0xFF, 0x00, 0x00, 0x04, 0x57, 0x07);
    }
}
