using OperatorPanel.Core.Ppi;
using OperatorPanel.TestKit;

namespace OperatorPanel.Core.Tests.Ppi;

public sealed class PpiFrameReaderTests
{
    [Fact]
    public void Append_CapturedExchangeOneByteAtATime_YieldsRequestAcknowledgePollAnswer()
    {
        // blueskit/siemens-s7-ppi-monitor s90 as it crossed the line: request, E5, poll, answer.
        var line = Hex.Parse(PpiCaptures.ReadVb300Request + " E5 " + PpiCaptures.Poll + " " + PpiCaptures.ReadVb300Answer);
        var reader = new PpiFrameReader();
        var frames = new List<PpiFrame>();

        foreach (var b in line)
        {
            reader.Append([b]);
            while (reader.TryTake(out var result))
            {
                result.Error.Should().Be(PpiFrameError.None);
                frames.Add(result.Frame!);
            }
        }

        frames.Select(f => f.ToString()).Should().Equal(
            "SD2 0->2 FC 7C 24 bytes", "SC E5", "SD1 0->2 FC 5C", "SD2 2->0 FC 08 30 bytes");
        reader.PendingChars.Should().Be(0);
    }

    [Fact]
    public void Append_AnswerWithE5And16InItsData_TakesThemAsData()
    {
        byte[] data = [0x32, 0xE5, 0x16, 0x68];
        var bytes = PpiFrameCodec.Encode(PpiFrame.Variable(0, 2, 0x08, data));
        var reader = new PpiFrameReader();

        reader.Append(bytes);

        reader.TryTake(out var result).Should().BeTrue();
        result.Frame!.Data.Should().Equal(data);
        reader.TryTake(out _).Should().BeFalse();
    }

    [Fact]
    public void Append_AnswerWithBadChecksum_ReportsItAndFindsNoPhantomAcknowledgeInside()
    {
        var bytes = PpiFrameCodec.Encode(PpiFrame.Variable(0, 2, 0x08, [0x32, 0xE5, 0x10]));
        bytes[^2] ^= 0x01;
        var reader = new PpiFrameReader();

        reader.Append(bytes);

        reader.TryTake(out var result).Should().BeTrue();
        result.Should().Match<PpiReadResult>(r => r.Frame == null && r.Error == PpiFrameError.ChecksumMismatch);
        reader.TryTake(out _).Should().BeFalse();
    }

    [Fact]
    public void Append_WrongEndCharacter_ReportsBadEnd()
    {
        var bytes = Hex.Parse(PpiCaptures.Poll);
        bytes[^1] = 0x17;
        var reader = new PpiFrameReader();

        reader.Append(bytes);

        reader.TryTake(out var result).Should().BeTrue();
        result.Error.Should().Be(PpiFrameError.BadEnd);
    }

    [Fact]
    public void Append_HeaderWhoseLengthsDiffer_IsDroppedByOneCharacterAndTheSearchGoesOn()
    {
        var reader = new PpiFrameReader();

        reader.Append(Hex.Parse("68 05 06 68 " + PpiCaptures.Poll));

        var results = new List<PpiReadResult>();
        while (reader.TryTake(out var result))
        {
            results.Add(result);
        }

        // 05 06 begin nothing; the second 68 begins a header that the poll's 10 02 00 then breaks; the 10 starts again.
        results.Select(r => r.Error).Should().Equal(PpiFrameError.BadHeader, PpiFrameError.BadHeader, PpiFrameError.None);
        results[1].SkippedBytes.Should().Be(2);
        results[2].Frame!.ToString().Should().Be("SD1 0->2 FC 5C");
    }

    [Fact]
    public void Append_NoiseBeforeAFrame_IsSkippedAndCounted()
    {
        var reader = new PpiFrameReader();

        reader.Append(Hex.Parse("00 FF 3C " + PpiCaptures.Poll));

        reader.TryTake(out var result).Should().BeTrue();
        result.SkippedBytes.Should().Be(3);
    }

    [Fact]
    public void Append_TokenFrame_IsReportedAsToken()
    {
        var reader = new PpiFrameReader();

        reader.Append([0xDC, 0x04, 0x01]);

        reader.TryTake(out var result).Should().BeTrue();
        result.Frame.Should().Be(PpiFrame.Token(4, 1));
    }

    [Fact]
    public void MissingChars_AfterTheHeader_CountsTheRestOfTheTelegram()
    {
        var reader = new PpiFrameReader();

        reader.Append(Hex.Parse("68 1B 1B 68"));

        reader.MissingChars.Should().Be(27 + 2);
    }
}
