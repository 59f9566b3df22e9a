using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Simulator.Reference;
using static OperatorPanel.Simulator.Tests.Reference.Exchange;

namespace OperatorPanel.Simulator.Tests.Reference;

/// <summary>DEFINE LIST and READ LIST on the reference model: the tail store, its capacity rule and every invalidation (docs/protocol-v2.md, "Lists").</summary>
public sealed class ReferencePlcListTests
{
    /// <summary>VD100 (4 bytes) and MB2: the list of the doc's examples 5.6.</summary>
    private const string TwoItems = "02 04006404 03000201";

    /// <summary>
    /// 20 items, 77 bytes: VB0-VB57 (58 bytes) and 19 single bytes VB100 .. VB136: tail 80 bytes, longest reply (READ
    /// CHANGES FULL) 20 + 154 = 174 characters, the most a 20-item list may have.
    /// </summary>
    private static readonly string FullList =
        "14 0400003A" + string.Concat(Enumerable.Range(0, 19).Select(i => $"04{100 + (2 * i):X4}01"));

    private readonly ReferencePlc _plc = new(new HandlerConfig(new Station(1), CpuProfiles.For(CpuModel.Cpu224)));

    public ReferencePlcListTests()
    {
        _plc.Memory.WriteWord(ProtocolArea.V, 100, 0);
        _plc.Memory.WriteWord(ProtocolArea.V, 102, 1111);
        _plc.Memory.M[2] = 0x05;
    }

    [Fact]
    public void DefineList_TwoItems_StoresDescriptorsBelowByte255AndLowersTheFloor()
    {
        Send(_plc, "01 01 05", "01 " + TwoItems)!.Payload.Should().Equal(0x00);

        _plc.Lists.Floor.Should().Be(248);
        _plc.Lists.Items(1).Should().Equal(new ReadItem(ProtocolArea.V, 100, 4), new ReadItem(ProtocolArea.M, 2, 1));
    }

    [Fact]
    public void ReadList_NeverDefinedOrOutsideOneToFour_Replies07()
    {
        Send(_plc, "01 01 06", "01")!.Payload.Should().Equal(0x07);
        Send(_plc, "01 02 06", "09")!.Payload.Should().Equal(0x07);
    }

    [Theory]
    [InlineData(113, true)]  // 20 + 226 = 246 <= 247: the request ends before the floor at 248
    [InlineData(114, false)] // 20 + 228 = 248: the request reaches the first descriptor
    public void LongWrite_ReachingTheTail_InvalidatesAndRedefineWorks(int length, bool kept)
    {
        Send(_plc, "01 01 05", "01 " + TwoItems);

        Send(_plc, "01 02 03", $"04 0400 {length:X2} " + new string('0', 2 * length))!.Payload[0].Should().Be(0x00);

        var read = Send(_plc, "01 03 06", "01")!;
        read.Payload.Should().Equal(kept ? [0x00, 0x00, 0x00, 0x04, 0x57, 0x05] : [0x07]);
        Send(_plc, "01 04 05", "01 " + TwoItems)!.Payload.Should().Equal(0x00);
        Send(_plc, "01 05 06", "01")!.Payload.Should().Equal(0x00, 0x00, 0x00, 0x04, 0x57, 0x05);
    }

    [Fact]
    public void DefineList_SecondListThatDoesNotFitWithTheFirst_Refuses04AndKeepsTheFirst()
    {
        Send(_plc, "01 01 05", "01 " + FullList)!.Payload.Should().Equal(0x00);

        // Floor 176 - 8 = 168, and list 1's longest reply of 20 + 154 = 174 characters would reach it.
        Send(_plc, "01 02 05", "02 02 04100001 04100201")!.Payload.Should().Equal(0x04);

        _plc.Lists.Floor.Should().Be(176);
        Send(_plc, "01 03 06", "01")!.Payload.Should().HaveCount(1 + 77).And.StartWith(new byte[] { 0x00 });
        Send(_plc, "01 04 06", "02")!.Payload.Should().Equal(0x07);
    }

    [Fact]
    public void DefineList_BadItems_RefusedLikeARead()
    {
        Send(_plc, "01 01 05", "01 01 04200001")!.Payload.Should().Equal(0x02);
        Send(_plc, "01 02 05", "01 01 04000000")!.Payload.Should().Equal(0x04);
        Send(_plc, "01 03 05", "07 01 04000001")!.Payload.Should().Equal(0x06);
        _plc.Lists.Floor.Should().Be(256);
    }

    [Fact]
    public void DefineList_RedefiningAList_ClearsEveryListFirst()
    {
        Send(_plc, "01 01 05", "01 " + TwoItems);
        Send(_plc, "01 02 05", "02 01 03000201");

        Send(_plc, "01 03 05", "01 01 04006404")!.Payload.Should().Equal(0x00);

        _plc.Lists.Floor.Should().Be(252);
        Send(_plc, "01 04 06", "02")!.Payload.Should().Equal(0x07);
        Send(_plc, "01 05 06", "01")!.Payload.Should().Equal(0x00, 0x00, 0x00, 0x04, 0x57);
    }

    [Fact]
    public void DefineList_DescriptorsWhoseAthWouldOverlapTheirSource_Refuses04BeforeTheItems()
    {
        // List 1 of 20 single bytes: floor 176. A list 2 of 14 items: 11 + 112 >= 176 - 56, so 04 comes before the
        // unknown area 09 of its first item could give 02 (its replies alone would fit: 48 <= 119).
        Send(_plc, "01 01 05", "01 14" + string.Concat(Enumerable.Range(0, 20).Select(i => $"04{i:X4}01")))!.Payload.Should().Equal(0x00);

        Send(_plc, "01 02 05", "02 0E 09000001" + string.Concat(Enumerable.Range(1, 13).Select(i => $"04{i:X4}01")))!
            .Payload.Should().Equal(0x04);

        _plc.Lists.Floor.Should().Be(176);
        Send(_plc, "01 03 05", "02 0D" + string.Concat(Enumerable.Range(0, 13).Select(i => $"04{i:X4}01")))!
            .Payload.Should().Equal(new byte[] { 0x00 }, "13 items: 11 + 104 < 176 - 52");
    }

    [Fact]
    public void DefineList_RedefinitionWithABadItem_HasClearedEveryListAnyway()
    {
        Send(_plc, "01 01 05", "01 " + TwoItems);

        Send(_plc, "01 02 05", "01 01 09000001")!.Payload.Should().Equal(0x02);

        _plc.Lists.Floor.Should().Be(256);
    }

    [Fact]
    public void Stop_ClearsEveryList()
    {
        Send(_plc, "01 01 05", "01 " + TwoItems);

        _plc.Mode = OperatingMode.Stop;
        _plc.Mode = OperatingMode.Run;

        Send(_plc, "01 02 06", "01")!.Payload.Should().Equal(0x07);
    }

    [Theory]
    [InlineData("01 04000010", true)]  // 16 bytes: 18 + 32 = 50 <= 175 - 4
    [InlineData("01 0400004C", true)]  // 76 bytes: 18 + 152 = 170 <= 171
    [InlineData("01 0400004D", false)] // 77 bytes: 18 + 154 = 172 > 171
    [InlineData("01 04000074", false)] // 116 bytes: 18 + 232 = 250 > 171
    public void Read_WhoseReplyWouldReachTheTail_InvalidatesButIsAnswered(string items, bool kept)
    {
        Send(_plc, "01 01 05", "01 " + FullList);

        var read = Send(_plc, "01 02 02", items)!;

        read.Payload.Should().HaveCount(1 + Hex(items)[4]).And.StartWith(new byte[] { 0x00 });
        Send(_plc, "01 03 06", "01")!.Payload.Should().HaveCount(kept ? 78 : 1);
    }

    [Fact]
    public void LongFrameForAnotherStation_ReachingTheTail_Invalidates()
    {
        Send(_plc, "01 01 05", "01 " + FullList);

        Send(_plc, "02 02 03", "04 0000 50 " + new string('0', 160)).Should().BeNull("it is station 2's frame");

        Send(_plc, "01 03 06", "01")!.Payload.Should().Equal(0x07);
    }

    [Fact]
    public void Identify_ShortReply_KeepsTheLists()
    {
        Send(_plc, "01 01 05", "01 " + FullList);

        Send(_plc, "01 02 01")!.Payload.Should().HaveCount(1 + 22);

        Send(_plc, "01 03 06", "01")!.Payload.Should().HaveCount(78);
    }
}
