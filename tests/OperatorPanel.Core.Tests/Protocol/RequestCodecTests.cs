using System.Collections.Immutable;
using System.Text;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Core.Tests.Protocol;

public sealed class RequestCodecTests
{
    private static readonly Station One = new(1);

    [Fact]
    public void Encode_ReadTwoItems_GivesTheAnnotatedFrame()
    {
        // 01 station, 08 seq, 02 READ, 02 items: V(04) 0064 len 04, I(01) 0000 len 02; CRC 16#A4DD as D, D, 4, A
        var request = new ReadRequest(One, 0x08, [new(ProtocolArea.V, 100, 4), new(ProtocolArea.I, 0, 2)]);

        Encoding.ASCII.GetString(RequestCodec.Encode(request)).Should().Be("<010802020400640401000002mmdj>");
    }

    [Fact]
    public void Encode_WriteBitSet_GivesTheAnnotatedFrame()
    {
        // 01 station, 0A seq, 04 WRITE BIT, Q(02) offset 0000, bit 05, value 01; then the check characters
        var request = new WriteBitRequest(One, 0x0A, ProtocolArea.Q, 0, 5, true);

        Encoding.ASCII.GetString(RequestCodec.Encode(request)).Should().Be("<010A040200000501dike>");
    }

    [Theory]
    [InlineData(21, 21)] // one item more than 20
    [InlineData(0, 0)]
    [InlineData(1, 117)] // 2 x 117 + 4 = 238 > 237
    [InlineData(8, 103)] // 206 + 32 = 238
    [InlineData(20, 79)] // 158 + 80 = 238
    public void Encode_ReadOutsideLimits_Throws(int items, int totalLength)
    {
        var request = new ReadRequest(One, 0, ReadItems(items, totalLength));

        var act = () => RequestCodec.Encode(request);

        act.Should().Throw<ArgumentOutOfRangeException>();
    }

    [Theory]
    [InlineData(1, 116)]
    [InlineData(8, 102)]
    [InlineData(20, 78)] // 2 x 78 + 4 x 20 = 236 <= 237
    public void Encode_ReadAtTheDataLimitForItsItemCount_ParsesBackUnchanged(int items, int totalLength)
    {
        var request = new ReadRequest(One, 0x21, ReadItems(items, totalLength));

        FrameCodec.TryDecode(RequestCodec.Encode(request), out var frame, out _).Should().BeTrue();

        RequestCodec.TryParse(frame, new FakeTarget(), out var parsed, out var error).Should().BeTrue();
        error.Should().Be(ProtocolError.None);
        parsed.Should().BeOfType<ReadRequest>().Which.Items.Should().Equal(request.Items);
    }

    [Theory]
    [InlineData(1, 116, ProtocolError.None)]
    [InlineData(1, 117, ProtocolError.BadLength)]
    [InlineData(2, 114, ProtocolError.None)]
    [InlineData(2, 115, ProtocolError.BadLength)]
    [InlineData(20, 78, ProtocolError.None)]
    [InlineData(20, 79, ProtocolError.BadLength)]
    [InlineData(21, 21, ProtocolError.BadLength)] // COUNT > 20, whatever the lengths
    public void TryParse_ReadAgainstTheTwoDPlusFourNRule_RefusesWithBadLengthPastTheLimit(int items, int totalLength, ProtocolError expected)
    {
        var payload = ReadItems(items, totalLength).SelectMany(i => new[] { (byte)i.Area, (byte)(i.Offset >> 8), (byte)i.Offset, (byte)i.Length });

        RequestCodec.TryParse(new FreeportFrame(1, 0, 2, [(byte)items, .. payload]), new FakeTarget(), out _, out var error)
            .Should().Be(expected == ProtocolError.None);

        error.Should().Be(expected);
    }

    [Fact]
    public void Encode_WriteBitAbove7_Throws()
    {
        var act = () => RequestCodec.Encode(new WriteBitRequest(One, 0, ProtocolArea.M, 0, 8, true));

        act.Should().Throw<ArgumentOutOfRangeException>();
    }

    [Theory]
    [InlineData("01 00 0A", "", ProtocolError.UnknownCommand)]
    [InlineData("01 00 00", "", ProtocolError.UnknownCommand)]
    [InlineData("01 00 01", "00", ProtocolError.BadLength)] //                  IDENTIFY with a payload
    [InlineData("01 00 02", "", ProtocolError.BadLength)] //                    READ without COUNT
    [InlineData("01 00 02", "00", ProtocolError.BadLength)] //                  COUNT 0
    [InlineData("01 00 02", "02 04000001", ProtocolError.BadLength)] //         COUNT 2, one item
    [InlineData("01 00 02", "01 04000000", ProtocolError.BadLength)] //         LENGTH 0
    [InlineData("01 00 02", "01 06000001", ProtocolError.AddressOutOfRange)] // area 06
    [InlineData("01 00 02", "01 00000001", ProtocolError.AddressOutOfRange)] // area 00
    [InlineData("01 00 02", "01 01000F02", ProtocolError.AddressOutOfRange)] // IB15 + 2 bytes > 16
    [InlineData("01 00 02", "02 01000F02 04000000", ProtocolError.AddressOutOfRange)] // first failing item decides
    [InlineData("01 00 02", "02 04000000 01000F02", ProtocolError.BadLength)]
    [InlineData("01 00 02", "02 04000072 04000001", ProtocolError.BadLength)] // 114 + 1 > 114 for two items
    [InlineData("01 00 03", "040000", ProtocolError.BadLength)] //             WRITE shorter than 7 bytes
    [InlineData("01 00 03", "04000002 AA", ProtocolError.BadLength)] //        LENGTH 2, one data byte
    [InlineData("01 00 03", "04000000", ProtocolError.BadLength)] //           LENGTH 0
    [InlineData("01 00 03", "07000001 AA", ProtocolError.AddressOutOfRange)]
    [InlineData("01 00 03", "04200001 AA", ProtocolError.AddressOutOfRange)] // VB8192 on a CPU 224
    [InlineData("01 00 03", "01000001 AA", ProtocolError.NotWritable)] //      I
    [InlineData("01 00 03", "05001C04 AABBCCDD", ProtocolError.NotWritable)] // SMB28-31 touches SMB28, SMB29
    [InlineData("01 00 04", "0200000501 00", ProtocolError.BadLength)]
    [InlineData("01 00 04", "02001000 01", ProtocolError.AddressOutOfRange)] // QB16
    [InlineData("01 00 04", "01000008 01", ProtocolError.NotWritable)] //      I, bit 8: 03 comes before 06
    [InlineData("01 00 04", "02000008 01", ProtocolError.BadParameter)] //     bit 8
    [InlineData("01 00 04", "02000000 02", ProtocolError.BadParameter)] //     value 02
    [InlineData("01 00 05", "01", ProtocolError.BadLength)] //                 DEFINE LIST without COUNT
    [InlineData("01 00 05", "01 00", ProtocolError.BadLength)] //              COUNT 0
    [InlineData("01 00 05", "01 15", ProtocolError.BadLength)] //              COUNT 21
    [InlineData("01 00 05", "01 02 04000001", ProtocolError.BadLength)] //     COUNT 2, one item
    [InlineData("01 00 05", "00 01 04000001", ProtocolError.BadParameter)] //  LIST 0
    [InlineData("01 00 05", "05 01 04000001", ProtocolError.BadParameter)] //  LIST 5
    [InlineData("01 00 05", "00 01 04000000", ProtocolError.BadParameter)] //  LIST before the items
    [InlineData("01 00 05", "01 01 04000000", ProtocolError.BadLength)] //     LENGTH 0
    [InlineData("01 00 05", "01 02 01000F02 04000000", ProtocolError.AddressOutOfRange)] // first failing item decides
    [InlineData("01 00 05", "01 02 04000072 04000001", ProtocolError.BadLength)] // 114 + 1 > 114 for two items
    [InlineData("01 00 06", "", ProtocolError.BadLength)] //                   READ LIST without LIST
    [InlineData("01 00 06", "01 01", ProtocolError.BadLength)] //              READ LIST with an extra byte
    [InlineData("01 00 07", "", ProtocolError.BadLength)] //                   STOP without its payload
    [InlineData("01 00 07", "535450", ProtocolError.BadLength)] //             "STP"
    [InlineData("01 00 07", "53544F50 00", ProtocolError.BadLength)] //        "STOP" and one byte more
    [InlineData("01 00 07", "53544F51", ProtocolError.BadParameter)] //        "STOQ"
    [InlineData("01 00 07", "73746F70", ProtocolError.BadParameter)] //        "stop"
    [InlineData("01 00 08", "01", ProtocolError.BadLength)] //                 READ CHANGES without FLAGS
    [InlineData("01 00 08", "01 00 00", ProtocolError.BadLength)] //           READ CHANGES with an extra byte
    [InlineData("01 00 08", "01 02", ProtocolError.BadParameter)] //           FLAGS bit 1
    [InlineData("01 00 08", "01 81", ProtocolError.BadParameter)] //           FULL and bit 7
    public void TryParse_RequestBreakingARule_GivesTheErrorCode(string head, string payload, ProtocolError expected)
    {
        RequestCodec.TryParse(Frame(head, payload), new FakeTarget(), out var request, out var error).Should().BeFalse();

        error.Should().Be(expected);
        request.Should().BeNull();
    }

    [Theory]
    [InlineData("01 00 81", "")] // a reply overheard on the bus
    [InlineData("00 00 01", "")] // station 0
    [InlineData("7F 00 01", "")] // station 127
    public void TryParse_FrameThatGetsNoReply_FailsWithoutErrorCode(string head, string payload)
    {
        RequestCodec.TryParse(Frame(head, payload), new FakeTarget(), out _, out var error).Should().BeFalse();

        error.Should().Be(ProtocolError.None);
    }

    [Fact]
    public void TryParse_WithoutTarget_SkipsSizeAndWritabilityChecks()
    {
        RequestCodec.TryParse(Frame("01 00 03", "01FFFF01 AA"), null, out var request, out _).Should().BeTrue();

        request.Should().BeOfType<WriteBlockRequest>().Which.Offset.Should().Be(0xFFFF);
    }

    /// <summary>V blocks 128 bytes apart: the first takes what the others (1 byte each) leave of the total.</summary>
    private static ImmutableArray<ReadItem> ReadItems(int count, int totalLength) =>
        [.. Enumerable.Range(0, count).Select(i => new ReadItem(ProtocolArea.V, i * 128, i == 0 ? totalLength - (count - 1) : 1))];

    private static FreeportFrame Frame(string head, string payload)
    {
        var h = Convert.FromHexString(head.Replace(" ", string.Empty, StringComparison.Ordinal));
        return new FreeportFrame(h[0], h[1], h[2], [.. Convert.FromHexString(payload.Replace(" ", string.Empty, StringComparison.Ordinal))]);
    }

    [Fact]
    public void TryParse_DefineListAndReadList_GiveTheRequests()
    {
        RequestCodec.TryParse(Frame("01 07 05", "02 02 04006404 03000201"), new FakeTarget(), out var define, out _).Should().BeTrue();
        RequestCodec.TryParse(Frame("01 08 06", "03"), new FakeTarget(), out var read, out _).Should().BeTrue();

        define.Should().BeEquivalentTo(new DefineListRequest(One, 7, 2, [new(ProtocolArea.V, 100, 4), new(ProtocolArea.M, 2, 1)]));
        read.Should().Be(new ReadListRequest(One, 8, 3));
    }

    [Fact]
    public void TryParse_StopAndReadChanges_GiveTheRequests()
    {
        RequestCodec.TryParse(Frame("01 09 07", "53544F50"), new FakeTarget(), out var stop, out _).Should().BeTrue();
        RequestCodec.TryParse(Frame("01 0A 08", "03 01"), new FakeTarget(), out var full, out _).Should().BeTrue();
        RequestCodec.TryParse(Frame("01 0B 08", "05 00"), new FakeTarget(), out var changes, out _).Should().BeTrue(); // list 5 parses: the station answers 07

        stop.Should().Be(new StopRequest(One, 9));
        full.Should().Be(new ReadChangesRequest(One, 0x0A, 3, Full: true));
        changes.Should().Be(new ReadChangesRequest(One, 0x0B, 5, Full: false));
    }

    [Theory]
    [InlineData("01 0C 09", "05", "", 1, 3)] //        lists 1 and 3
    [InlineData("01 0D 09", "0F", "", 1, 2, 3, 4)] //  all four
    [InlineData("01 0E 09", "00", "BadParameter")] //   no list
    [InlineData("01 0E 09", "13", "BadParameter")] //   a bit outside 0-3
    [InlineData("01 0E 09", "0300", "BadLength")] //    body 5 bytes
    [InlineData("01 0E 09", "", "BadLength")] //        no MASK
    public void TryParse_ReadChangesOfLists_TakesAMaskOfListsOneToFour(string head, string payload, string error, params int[] lists)
    {
        var parsed = RequestCodec.TryParse(Frame(head, payload), new FakeTarget(), out var request, out var code);

        parsed.Should().Be(error.Length == 0);
        if (parsed)
        {
            request.Should().BeOfType<ReadChangesOfListsRequest>().Which.Lists.Should().Equal(lists);
        }
        else
        {
            code.ToString().Should().Be(error);
        }
    }

    [Fact]
    public void Encode_ReadChangesOfLists_SendsTheMaskInFourteenCharacters()
    {
        var request = new ReadChangesOfListsRequest(One, 1, ReadChangesOfListsRequest.MaskOf([2, 4]));

        RequestCodec.ToFrame(request).Payload.Should().Equal(0x0A);
        RequestCodec.Encode(request).Length.Should().Be(ProtocolLimits.RequestChars(1)).And.Be(14);
        FluentActions.Invoking(() => RequestCodec.Encode(request with { ListMask = 0 })).Should().Throw<ArgumentOutOfRangeException>();
        FluentActions.Invoking(() => RequestCodec.Encode(request with { ListMask = 0x10 })).Should().Throw<ArgumentOutOfRangeException>();
    }

    [Fact]
    public void Encode_StopAndReadChanges_GiveTheirPayloads()
    {
        RequestCodec.ToFrame(new StopRequest(One, 1)).Payload.Should().Equal("STOP"u8.ToArray());
        RequestCodec.ToFrame(new ReadChangesRequest(One, 1, 2, Full: true)).Payload.Should().Equal(2, 1);
        RequestCodec.ToFrame(new ReadChangesRequest(One, 1, 4, Full: false)).Payload.Should().Equal(4, 0);
        ProtocolLimits.RequestChars(2).Should().Be(RequestCodec.Encode(new ReadChangesRequest(One, 1, 4, Full: false)).Length).And.Be(16);
    }

    [Theory]
    [InlineData(0)]
    [InlineData(5)]
    public void Encode_ListIdOutsideOneToFour_Throws(int list)
    {
        var act = () => RequestCodec.Encode(new ReadListRequest(One, 0, list));

        act.Should().Throw<ArgumentOutOfRangeException>();
    }
}
