using OperatorPanel.Core.Ppi;
using OperatorPanel.Core.Ppi.S7;
using OperatorPanel.TestKit;

namespace OperatorPanel.Core.Tests.Ppi;

public sealed class PpiFrameCodecTests
{
    [Fact]
    public void Encode_PollOfStation2_IsThePublishedConfirmFrame()
    {
        var poll = PpiFrameCodec.Encode(PpiFrame.Fixed(2, 0, PpiFunctionCode.Poll(frameCountBit: false)));

        Hex.Format(poll).Should().Be(PpiCaptures.Poll);
    }

    [Fact]
    public void Encode_ReadRequestWithCapturedFunctionCode_MatchesTheCaptureByteForByte()
    {
        var job = S7JobCodec.Read(0x2658, [S7Item.Bytes(S7Area.V, 300, 12)]);

        var frame = PpiFrameCodec.Encode(PpiFrame.Variable(2, 0, PpiFunctionCode.Poll(frameCountBit: true), job));

        Hex.Format(frame).Should().Be(Hex.Format(Hex.Parse(PpiCaptures.ReadVb300Request)));
    }

    [Theory]
    [InlineData(false, 0x5C)]
    [InlineData(true, 0x7C)]
    public void Poll_FrameCountBit_GivesTheTwoPollCodes(bool frameCountBit, byte expected)
    {
        PpiFunctionCode.Poll(frameCountBit).Should().Be(expected);
        PpiFunctionCode.IsSendRequestData(expected).Should().BeTrue();
        PpiFunctionCode.HasValidFrameCount(expected).Should().BeTrue();
    }

    [Fact]
    public void FirstRequest_Is6CWithFrameCountBitSetAndNotValid()
    {
        PpiFunctionCode.FirstRequest.Should().Be(0x6C);
        PpiFunctionCode.FrameCount(0x6C).Should().BeTrue();
        PpiFunctionCode.HasValidFrameCount(0x6C).Should().BeFalse();
    }

    [Fact]
    public void Encode_TokenAndShortAcknowledge_AreThreeAndOneCharacters()
    {
        Hex.Format(PpiFrameCodec.Encode(PpiFrame.Token(3, 1))).Should().Be("DC 03 01");
        Hex.Format(PpiFrameCodec.Encode(PpiFrame.ShortAcknowledge)).Should().Be("E5");
    }

    [Fact]
    public void Checksum_SumsModulo256()
    {
        PpiFrameCodec.Checksum([0xFF, 0x02, 0x03]).Should().Be(0x04);
    }

    [Fact]
    public void Variable_MoreThan246DataBytes_Throws()
    {
        var act = () => PpiFrame.Variable(2, 0, 0x6C, new byte[247]);

        act.Should().Throw<ArgumentOutOfRangeException>();
    }
}
