using OperatorPanel.Cli.Bench.V3;

namespace OperatorPanel.Cli.Tests.Bench.V3;

public sealed class LenRuleForwarderTests
{
    private static readonly TimeSpan Byte = TimeSpan.FromMilliseconds(1);

    [Fact]
    public void Receive_DataHoldsGreaterAndLessThan_WholeAtTheLenthByteNotAtAValue()
    {
        // LEN 10: data bytes '>' and '<' inside must not end (or restart) the frame.
        byte[] frame = [(byte)'<', 10, 0x80, (byte)'>', (byte)'<', (byte)'>', 1, 2, 3, 4];

        var (whole, dropped) = LenRuleForwarder.Receive(LenRuleForwarder.BackToBack(frame, Byte), Byte, TimeSpan.FromMilliseconds(4), 9);

        whole.Should().Be(TimeSpan.FromMilliseconds(10));
        dropped.Should().Be(0);
    }

    [Fact]
    public void Receive_NoiseBeforeTheStart_SkippedAndFrameWholeAtItsEnd()
    {
        byte[] bytes = [0x00, 0x3E, (byte)'<', 9, 0x81, 0, 0, 0, 0, 0, 0];

        var (whole, _) = LenRuleForwarder.Receive(LenRuleForwarder.BackToBack(bytes, Byte), Byte, TimeSpan.FromMilliseconds(4), 9);

        whole.Should().Be(TimeSpan.FromMilliseconds(11));
    }

    [Fact]
    public void Receive_PauseOverTheIdleLimit_PartialDroppedNeverWhole()
    {
        var timed = LenRuleForwarder.BackToBack([(byte)'<', 9, 0x81, 0, 0, 0, 0, 0, 0], Byte)
            .Select((b, i) => (b.Value, i >= 5 ? b.At + TimeSpan.FromMilliseconds(5) : b.At)).ToList();

        var (whole, dropped) = LenRuleForwarder.Receive(timed, Byte, TimeSpan.FromMilliseconds(4), 9);

        whole.Should().BeNull();
        dropped.Should().Be(1);
    }
}
