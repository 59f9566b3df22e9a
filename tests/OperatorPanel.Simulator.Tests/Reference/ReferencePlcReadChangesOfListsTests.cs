using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Simulator.Reference;
using static OperatorPanel.Simulator.Tests.Reference.Exchange;

namespace OperatorPanel.Simulator.Tests.Reference;

/// <summary>
/// 09 READ CHANGES OF LISTS on the reference model (docs/protocol-v2.md, "09 READ CHANGES OF LISTS"): one entry per list
/// of MASK, K pairs or REREAD, each REREAD reason, the copy invalid after it, the checks 04, 06, 07 in order, FEATURES.
/// </summary>
public sealed class ReferencePlcReadChangesOfListsTests
{
    /// <summary>List 1: VD100 and MB2 (D = 5); list 2: QB0 (D = 1); list 3: VB200-VB203 (D = 4).</summary>
    private static ReferencePlc Plc(int copyBytes = HandlerMemory.DefaultCopyBytes)
    {
        var plc = new ReferencePlc(new HandlerConfig(new Station(1), CpuProfiles.For(CpuModel.Cpu224), copyBytes: copyBytes));
        plc.Memory.WriteDoubleWord(ProtocolArea.V, 100, 1111);
        (plc.Memory.M[2], plc.Memory.Q[0]) = (0x05, 0x01);
        Send(plc, "01 01 05", "01 02 04006404 03000201")!.Payload.Should().Equal(0x00);
        Send(plc, "01 02 05", "02 01 02000001")!.Payload.Should().Equal(0x00);
        Send(plc, "01 03 05", "03 01 0400C804")!.Payload.Should().Equal(0x00);
        return plc;
    }

    private static byte[] Lists(ReferencePlc plc, byte mask) => [.. Send(plc, "01 30 09", $"{mask:X2}")!.Payload];

    private static byte[] Changes(ReferencePlc plc, int list) => [.. Send(plc, "01 31 08", $"{list:X2} 00")!.Payload];

    [Fact]
    public void ReadChangesOfLists_CopiesNotFilledYet_AnswersRereadForEachList()
    {
        Lists(Plc(), 0b0111).Should().Equal(0x00, 0xFE, 0xFE, 0xFE);
    }

    [Fact]
    public void ReadChangesOfLists_IdleAndChangedLists_AnswersOneEntryEachInListOrder()
    {
        var plc = Plc();
        Changes(plc, 1);
        Changes(plc, 3);
        plc.Memory.V[202] = (byte)~plc.Memory.V[202];

        Lists(plc, 0b0101).Should().Equal(0x00, 0x00, 0x01, 0x02, plc.Memory.V[202]);
        Lists(plc, 0b0101).Should().Equal(0x00, 0x00, 0x00);
    }

    [Fact]
    public void ReadChangesOfLists_PairsNotShorter_AnswersRereadAndTheNextReadChangesAnswersFull()
    {
        var plc = Plc();
        Changes(plc, 1);
        Changes(plc, 2);
        plc.Memory.Q[0] = 0x03;

        Lists(plc, 0b0011).Should().Equal(0x00, 0x00, 0xFE);
        Changes(plc, 2).Should().Equal(0x00, 0xFF, 0x03);
        Lists(plc, 0b0011).Should().Equal(0x00, 0x00, 0x00);
    }

    [Fact]
    public void ReadChangesOfLists_ListWithoutCopy_AnswersRereadEveryTime()
    {
        // 5 copy bytes: list 1 takes them all, lists 2 and 3 have none.
        var plc = Plc(copyBytes: 5);
        Changes(plc, 1);
        Changes(plc, 2);

        Lists(plc, 0b0011).Should().Equal(0x00, 0x00, 0xFE);
        Lists(plc, 0b0011).Should().Equal(0x00, 0x00, 0xFE);
    }

    [Theory]
    [InlineData("", 0x04)]
    [InlineData("03 00", 0x04)]
    [InlineData("00", 0x06)]
    [InlineData("10", 0x06)]
    [InlineData("19", 0x06)]
    [InlineData("08", 0x07)]
    [InlineData("0F", 0x07)]
    public void ReadChangesOfLists_BadLengthMaskOrUndefinedList_AnswersTheFirstFailingCheck(string payload, byte error)
    {
        Send(Plc(), "01 32 09", payload)!.Payload.Should().Equal(error);
    }

    [Fact]
    public void Identify_FeaturesBit2_Says09IsPresent()
    {
        var features = Send(Plc(), "01 33 01")!.Payload[1 + 20];

        (features & HandlerIdentity.ChangesOfListsFeature).Should().Be(HandlerIdentity.ChangesOfListsFeature);
    }
}
