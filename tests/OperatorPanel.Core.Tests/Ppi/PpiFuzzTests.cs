using OperatorPanel.Core.Ppi;
using OperatorPanel.Core.Ppi.S7;
using OperatorPanel.TestKit;

namespace OperatorPanel.Core.Tests.Ppi;

/// <summary>Bytes off a noisy line and PDUs from strangers: the readers answer with an error, never with an exception.</summary>
public sealed class PpiFuzzTests
{
    private static readonly string[] Captures =
    [
        PpiCaptures.ReadVb300Request, PpiCaptures.ReadVb300Answer, PpiCaptures.ReadSevenItemsRequest, PpiCaptures.ReadSevenItemsAnswer,
        PpiCaptures.WriteVd300Request, PpiCaptures.WriteVd300Answer, PpiCaptures.ReadTimersAnswer, PpiCaptures.StopRequest,
    ];

    [Fact]
    public void Reader_RandomLineNoise_NeverThrowsAndEveryFrameItYieldsIsSound()
    {
        var random = new Random(20);
        var reader = new PpiFrameReader();
        for (var round = 0; round < 3000; round++)
        {
            var noise = new byte[random.Next(1, 64)];
            random.NextBytes(noise);
            reader.Append(noise);
            while (reader.TryTake(out var result))
            {
                if (result.Frame is { } frame)
                {
                    var again = new PpiFrameReader();
                    again.Append(PpiFrameCodec.Encode(frame));
                    again.TryTake(out var reread).Should().BeTrue();
                    reread.Frame.Should().Be(frame);
                }
            }
        }
    }

    [Fact]
    public void Decoders_CapturesWithOneByteChanged_AnswerWithAnErrorOrAValueNeverAnException()
    {
        var random = new Random(21);
        foreach (var capture in Captures)
        {
            var pdu = PpiCaptures.Pdu(capture);
            for (var round = 0; round < 400; round++)
            {
                var mutated = (byte[])pdu.Clone();
                mutated[random.Next(mutated.Length)] = (byte)random.Next(256);
                var cut = mutated.AsSpan(0, random.Next(mutated.Length + 1));

                S7JobDecoder.TryDecode(cut, out _, out _);
                S7AnswerDecoder.TryRead(cut, 0x2659, [S7Item.Bytes(S7Area.I, 0, 2), S7Item.Bytes(S7Area.Q, 0, 1)], out _, out _);
                S7AnswerDecoder.TryWrite(cut, 0x2734, 1, out _, out _);
                S7AnswerDecoder.TrySetupCommunication(cut, 0, out _, out _);
            }
        }
    }
}
