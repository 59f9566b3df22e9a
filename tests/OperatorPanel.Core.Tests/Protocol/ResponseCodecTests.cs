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
        // 01 station, 08 seq, 82 READ reply, 00 OK, VD100 = 00000457, IB0 = A5, IB1 = 03; BCC 72
        ResponseCodec.TryDecode("<0108820000000457A50372>"u8, Read, out var response, out var error).Should().BeTrue();

        error.Should().Be(FrameError.None);
        response.Should().BeOfType<ReadResponse>().Which.Data.Should().Equal(0x00, 0x00, 0x04, 0x57, 0xA5, 0x03);
    }

    [Fact]
    public void TryDecode_IdentifyReply_GivesEveryField()
    {
        var request = new IdentifyRequest(new Station(1), 0x07);

        ResponseCodec.TryDecode("<01078100010103010F7705200100030002000975>"u8, request, out var response, out _).Should().BeTrue();

        response.Should().Be(new IdentifyResponse(new Station(1), 0x07, 1, 1, 3, 1, 0x0F, 119, 5, 0x20, 1, 3, 2, 9));
    }

    [Fact]
    public void TryDecode_ErrorReply_GivesErrorResponse()
    {
        var request = new WriteBlockRequest(new Station(1), 0x0B, ProtocolArea.I, 0, [0x01]);
        var chars = ResponseCodec.Encode(new ErrorResponse(new Station(1), 0x0B, CommandCode.Write, ProtocolError.NotWritable));

        Encoding.ASCII.GetString(chars).Should().Be("<010B83037B>");
        ResponseCodec.TryDecode(chars, request, out var response, out _).Should().BeTrue();
        response.Should().Be(new ErrorResponse(new Station(1), 0x0B, CommandCode.Write, ProtocolError.NotWritable));
    }

    [Theory]
    [InlineData("01 08 02", "00 00000457A503", FrameError.NotAReply)] //     our own request echoed
    [InlineData("02 08 82", "00 00000457A503", FrameError.StationMismatch)]
    [InlineData("01 07 82", "00 00000457A503", FrameError.SequenceMismatch)] // a late reply to request 07
    [InlineData("01 08 83", "00 00000457A503", FrameError.CommandMismatch)]
    [InlineData("01 08 82", "00 00000457A5", FrameError.LengthMismatch)] //  5 data bytes for 6 asked
    [InlineData("01 08 82", "", FrameError.LengthMismatch)] //                no STATUS
    [InlineData("01 08 82", "02 00", FrameError.LengthMismatch)] //           an error status carries no data
    [InlineData("01 08 82", "01", FrameError.UnknownStatus)] //               01 is never sent
    [InlineData("01 08 82", "08", FrameError.UnknownStatus)]
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
        ResponseCodec.TryDecode("<0108820000000457A50373>"u8, Read, out _, out var error).Should().BeFalse();

        error.Should().Be(FrameError.ChecksumMismatch);
    }
}
