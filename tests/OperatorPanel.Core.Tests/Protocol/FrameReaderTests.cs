using System.Text;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Core.Tests.Protocol;

public sealed class FrameReaderTests
{
    [Fact]
    public void Append_FrameInSingleBytes_YieldsItOnceComplete()
    {
        var reader = new FrameReader();
        var frame = Encoding.ASCII.GetBytes("<010701dl`l>");

        foreach (var b in frame[..^1])
        {
            reader.Append([b]);
            reader.TryTake(out _).Should().BeFalse();
        }

        reader.Append(frame.AsSpan(frame.Length - 1));
        reader.TryTake(out var result).Should().BeTrue();
        result.Should().Match<FrameReadResult>(r => r.IsFrame && r.SkippedBytes == 0);
        result.Frame.Should().Equal(frame);
    }

    [Fact]
    public void Append_NoiseBeforeStart_IsSkippedAndCounted()
    {
        var reader = new FrameReader();

        reader.Append([0x00, 0xFF, (byte)'>', (byte)'1', (byte)'2']);
        reader.Append("<010701dl`l>"u8);

        reader.TryTake(out var result).Should().BeTrue();
        Encoding.ASCII.GetString(result.Frame.AsSpan()).Should().Be("<010701dl`l>");
        result.SkippedBytes.Should().Be(5);
    }

    [Fact]
    public void Append_StartInsideFrame_RestartsTheFrameAtTheLastStart()
    {
        var reader = new FrameReader();

        reader.Append("<0108<01<010701dl`l>"u8);

        reader.TryTake(out var result).Should().BeTrue();
        Encoding.ASCII.GetString(result.Frame.AsSpan()).Should().Be("<010701dl`l>");
        FrameCodec.TryDecode(result.Frame.AsSpan(), out _, out _).Should().BeTrue();
        result.SkippedBytes.Should().Be(8);
        reader.TryTake(out _).Should().BeFalse();
    }

    [Fact]
    public void Append_255CharactersWithoutEnd_ReportsTooLongAndResyncs()
    {
        var reader = new FrameReader();

        reader.Append(Encoding.ASCII.GetBytes("<" + new string('A', 254) + "AB<010701dl`l>"));

        reader.TryTake(out var tooLong).Should().BeTrue();
        tooLong.Error.Should().Be(FrameError.TooLong);
        tooLong.Frame.Should().BeEmpty();
        reader.TryTake(out var next).Should().BeTrue();
        next.IsFrame.Should().BeTrue();
        next.SkippedBytes.Should().Be(2);
        Encoding.ASCII.GetString(next.Frame.AsSpan()).Should().Be("<010701dl`l>");
    }

    [Fact]
    public void Append_255thCharacterIsEnd_YieldsTheFrame()
    {
        var reader = new FrameReader();
        var text = "<" + new string('0', 253) + ">";

        reader.Append(Encoding.ASCII.GetBytes(text));

        reader.TryTake(out var result).Should().BeTrue();
        result.IsFrame.Should().BeTrue();
        result.Frame.Should().HaveCount(255);
    }

    [Fact]
    public void Reset_PartialFrame_IsForgotten()
    {
        var reader = new FrameReader();
        reader.Append("<0107"u8);

        reader.Reset();
        reader.Append("01dl`l>"u8);

        reader.TryTake(out _).Should().BeFalse();
        reader.PendingChars.Should().Be(0);
    }
}
