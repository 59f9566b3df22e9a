using System.Text;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Core.Tests.Protocol;

public sealed class ResponseCodecTests
{
    private static readonly ReadRequest Read = new(new Station(1), 0x08, [new(ProtocolArea.V, 100, 4), new(ProtocolArea.I, 0, 2)]);

    [Fact]
    public void TryDecode_ReadReply_GivesTheDataInItemOrder()
    {
        // 01 station, 08 seq, 82 READ reply, 00 OK, REQCHECK A4DD (the request's CRC), VD100 = 00000457, IB0 = A5, IB1 = 03
        RequestCodec.Check(Read).Should().Be(0xA4DD);
        ResponseCodec.TryDecode("<01088200A4DD00000457A503jnic>"u8, Read, out var response, out var error).Should().BeTrue();

        error.Should().Be(FrameError.None);
        response.Should().BeOfType<ReadResponse>().Which.Data.Should().Equal(0x00, 0x00, 0x04, 0x57, 0xA5, 0x03);
    }

    [Fact]
    public void TryDecode_IdentifyReply_GivesEveryField()
    {
        var request = new IdentifyRequest(new Station(1), 0x07);

        // v1's 15 bytes (protocol 02, MAX_READ_DATA 74 = 116), then port 0, V_FIRST 1E54 = 7764, V_BYTES 01AC = 428,
        // FEATURES 02 (copies, no STOP), COPY_BYTES 78 = 120
        ResponseCodec.TryDecode("<01078100C0C4020103010F74052001000300020009001E5401AC0278cecc>"u8, request, out var response, out _).Should().BeTrue();

        response.Should().Be(new IdentifyResponse(new Station(1), 0x07, 2, 1, 3, 1, 0x0F, 116, 5, 0x20, 1, 3, 2, 9, 0, 7764, 428, 2, 120) { RequestCheck = 0xC0C4 });
        var identity = (IdentifyResponse)response;
        (identity.StopEnabled, identity.HasCopies).Should().Be((false, true));
    }

    [Fact]
    public void TryDecode_ErrorReply_GivesErrorResponse()
    {
        var request = new WriteBlockRequest(new Station(1), 0x0B, ProtocolArea.I, 0, [0x01]);
        var chars = ResponseCodec.Encode(new ErrorResponse(new Station(1), 0x0B, CommandCode.Write, ProtocolError.NotWritable), request);

        Encoding.ASCII.GetString(chars).Should().Be("<010B830340E3blge>"); // REQCHECK 40E3: the CRC of <010B030100000101cn`d>
        ResponseCodec.TryDecode(chars, request, out var response, out _).Should().BeTrue();
        response.Should().Be(new ErrorResponse(new Station(1), 0x0B, CommandCode.Write, ProtocolError.NotWritable) { RequestCheck = 0x40E3 });
    }

    [Theory]
    [InlineData("01 08 02", "00 A4DD 00000457A503", FrameError.NotAReply)] //     our own request echoed
    [InlineData("02 08 82", "00 A4DD 00000457A503", FrameError.StationMismatch)]
    [InlineData("01 07 82", "00 A4DD 00000457A503", FrameError.SequenceMismatch)] // a late reply to request 07
    [InlineData("01 08 83", "00 A4DD 00000457A503", FrameError.CommandMismatch)]
    [InlineData("01 08 82", "00 A4DC 00000457A503", FrameError.RequestCheckMismatch)] // the PLC read another frame
    [InlineData("01 08 82", "02 A4DC", FrameError.RequestCheckMismatch)] //       a refusal of another frame is no refusal
    [InlineData("01 08 82", "00 A4DD 00000457A5", FrameError.LengthMismatch)] //  5 data bytes for 6 asked
    [InlineData("01 08 82", "", FrameError.LengthMismatch)] //                     no STATUS
    [InlineData("01 08 82", "00 A4", FrameError.LengthMismatch)] //                half a REQCHECK
    [InlineData("01 08 82", "02 A4DD 00", FrameError.LengthMismatch)] //           an error status carries no data
    [InlineData("01 08 82", "01 A4DD", FrameError.UnknownStatus)] //               01 is never sent
    [InlineData("01 08 82", "08 A4DD", FrameError.UnknownStatus)]
    public void TryDecode_ReplyNotAnsweringTheRequest_ReportsTheError(string head, string payload, FrameError expected)
    {
        var h = Convert.FromHexString(head.Replace(" ", string.Empty, StringComparison.Ordinal));
        var frame = new FreeportFrame(h[0], h[1], h[2], [.. Convert.FromHexString(payload.Replace(" ", string.Empty, StringComparison.Ordinal))]);

        ResponseCodec.TryDecode(FrameCodec.Encode(frame), Read, out _, out var error).Should().BeFalse();

        error.Should().Be(expected);
    }

    [Fact]
    public void TryDecode_BadFrame_ReportsTheFramingError()
    {
        ResponseCodec.TryDecode("<01088200A4DD00000457A503jnid>"u8, Read, out _, out var error).Should().BeFalse();

        error.Should().Be(FrameError.ChecksumMismatch);
    }

    [Theory]
    [InlineData("00", true, "")] //                       idle: no pairs
    [InlineData("02 0012 0400", true, "0012 0400")] //    two pairs, ascending
    [InlineData("FF 0000045705", true, "")] //            FULL: the whole list
    [InlineData("02 0400 0012", false, "")] //            indexes not ascending
    [InlineData("02 0012 0012", false, "")] //            an index twice
    [InlineData("01 0012 04", false, "")] //              K = 1, one and a half pairs
    [InlineData("80", false, "")] //                      K = 128: neither a pair count nor FULL
    [InlineData("FF", false, "")] //                      FULL without data
    [InlineData("", false, "")] //                        no K
    public void TryDecode_ReadChangesReply_TakesPairsOrFullAndRefusesAnythingElse(string payload, bool valid, string pairs)
    {
        var request = new ReadChangesRequest(new Station(1), 0x17, 1, Full: false);
        var check = RequestCodec.Check(request);
        var frame = new FreeportFrame(1, 0x17, 0x88, [0x00, (byte)(check >> 8), (byte)check, .. Hex(payload)]);

        ResponseCodec.TryDecode(FrameCodec.Encode(frame), request, out var response, out var error).Should().Be(valid, error.ToString());

        if (valid)
        {
            var changes = (ReadChangesResponse)response;
            changes.Full.Should().Be(Hex(payload)[0] == 0xFF);
            changes.Changes.SelectMany(c => new[] { c.Index, c.Value }).Should().Equal(Hex(pairs));
        }
        else
        {
            error.Should().Be(FrameError.LengthMismatch);
        }
    }

    [Theory]
    [InlineData("00 00", true, "1:;3:")] //                     both idle
    [InlineData("01 0012 FE", true, "1:0012;3:reread")] //     one pair in list 1, list 3 to be read again
    [InlineData("FE 02 0012 0400", true, "1:reread;3:0012 0400")]
    [InlineData("00", false, "")] //                           an entry missing
    [InlineData("00 00 00", false, "")] //                     an entry too many
    [InlineData("02 0400 0012 00", false, "")] //              indexes not ascending within an entry
    [InlineData("80 00", false, "")] //                        K = 128
    [InlineData("FF 0000 00", false, "")] //                   FULL is not an entry of 09
    [InlineData("01 0012", false, "")] //                      list 3's K missing after list 1's pair
    public void TryDecode_ReadChangesOfListsReply_TakesOneEntryPerListOfTheMask(string payload, bool valid, string entries)
    {
        var request = new ReadChangesOfListsRequest(new Station(1), 0x1D, ReadChangesOfListsRequest.MaskOf([1, 3]));
        var check = RequestCodec.Check(request);
        var frame = new FreeportFrame(1, 0x1D, 0x89, [0x00, (byte)(check >> 8), (byte)check, .. Hex(payload)]);

        ResponseCodec.TryDecode(FrameCodec.Encode(frame), request, out var response, out var error).Should().Be(valid, error.ToString());

        if (valid)
        {
            var lists = ((ReadChangesOfListsResponse)response).Lists;
            string.Join(';', lists.Select(l => $"{l.List}:" + (l.Reread ? "reread" : string.Join(' ', l.Changes.Select(c => $"{c.Index:X2}{c.Value:X2}")))))
                .Should().Be(entries);
            ResponseCodec.Encode(response).Should().Equal(FrameCodec.Encode(frame), "the entries encode back to the same frame");
        }
        else
        {
            error.Should().Be(FrameError.LengthMismatch);
        }
    }

    [Fact]
    public void ListChanges_TryApply_PutsTheChangesOverWhatThePcHeldAndARereadGivesNothing()
    {
        var entry = ListChanges.Pairs(2, [new ChangedByte(1, 0x34)]);

        entry.TryApply([0x00, 0x00, 0x05], out var current).Should().BeTrue();
        current.Should().Equal(0x00, 0x34, 0x05);
        entry.TryApply([0x00], out _).Should().BeFalse("index 1 lies outside a 1-byte list");
        ListChanges.RereadList(2).TryApply([0x00, 0x00], out _).Should().BeFalse("a REREAD entry carries no values");
    }

    [Fact]
    public void ReadChangesResponse_TryApply_PutsTheChangesOverWhatThePcHeld()
    {
        var pairs = ReadChangesResponse.Pairs(new Station(1), 1, [new ChangedByte(0, 0x12), new ChangedByte(4, 0x07)]);

        pairs.TryApply([0x00, 0x00, 0x04, 0x57, 0x05], out var current).Should().BeTrue();
        current.Should().Equal(0x12, 0x00, 0x04, 0x57, 0x07);
        pairs.TryApply([0x00, 0x00], out _).Should().BeFalse("index 4 lies outside a 2-byte list");
        ReadChangesResponse.Whole(new Station(1), 1, [1, 2]).TryApply([9, 9, 9], out var whole).Should().BeTrue();
        whole.Should().Equal(1, 2);
    }

    [Fact]
    public void TryDecode_ReplyEncodedForTheRequest_CarriesItsCheckAndAnotherRequestsReplyDoesNot()
    {
        var write = new WriteBlockRequest(new Station(1), 0x21, ProtocolArea.V, 100, [0x12, 0x34]);
        var other = write with { Offset = 101 };
        var reply = ResponseCodec.Encode(new WriteBlockResponse(new Station(1), 0x21, [0x12, 0x34]), other);

        ResponseCodec.TryDecode(reply, other, out var confirmed, out _).Should().BeTrue();
        confirmed.RequestCheck.Should().Be(RequestCodec.Check(other));
        ResponseCodec.TryDecode(reply, write, out var response, out var error).Should().BeFalse("VB101 was written, not VB100");
        error.Should().Be(FrameError.RequestCheckMismatch);
        response.Should().BeNull();
    }

    private static byte[] Hex(string text) => Convert.FromHexString(text.Replace(" ", string.Empty, StringComparison.Ordinal));
}
