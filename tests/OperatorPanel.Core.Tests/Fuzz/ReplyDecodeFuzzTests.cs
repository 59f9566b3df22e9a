using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Tests.Protocol;

namespace OperatorPanel.Core.Tests.Fuzz;

/// <summary>
/// Mutated replies (<see cref="ReplyMutator"/>) fed to <see cref="ResponseCodec"/> and <see cref="FrameReader"/>:
/// only a well-formed reply that answers the request is accepted, everything else is a named
/// <see cref="FrameError"/>, and nothing throws. Seeded, so a failure names a reproducible case.
/// </summary>
public sealed class ReplyDecodeFuzzTests
{
    [Fact]
    public void TryDecode_MutatedReplies_AcceptsOnlyAReplyThatAnswersTheRequest()
    {
        var random = new Random(485);
        var failures = new List<string>();
        for (var i = 0; i < 4000; i++)
        {
            var request = RandomMessages.Request(random);
            var reply = ResponseCodec.Encode(RandomMessages.ResponseTo(random, request));
            var mutation = ReplyMutator.Mutate(reply, request, random);
            var because = $"case {i}, {request.Command}, {mutation.How}";
            try
            {
                var accepted = ResponseCodec.TryDecode(mutation.Chars, request, out var response, out var error);
                if (accepted && !mutation.MayBeAccepted)
                {
                    failures.Add($"{because}: accepted");
                }
                else if (accepted && !ResponseCodec.Encode(response).AsSpan().SequenceEqual(mutation.Chars))
                {
                    failures.Add($"{because}: accepted, but the response does not encode back to the characters");
                }
                else if (!accepted && error == FrameError.None)
                {
                    failures.Add($"{because}: refused without naming a FrameError");
                }
            }
            catch (Exception ex) when (ex is not OutOfMemoryException)
            {
                failures.Add($"{because}: {ex.GetType().Name} {ex.Message}");
            }
        }

        failures.Should().BeEmpty();
    }

    [Fact]
    public void TryDecode_UntouchedReplies_AreAllAccepted()
    {
        var random = new Random(486);
        for (var i = 0; i < 500; i++)
        {
            var request = RandomMessages.Request(random);
            var reply = ResponseCodec.Encode(RandomMessages.ResponseTo(random, request));

            ResponseCodec.TryDecode(reply, request, out _, out var error).Should().BeTrue($"case {i}: {request.Command} ({error})");
        }
    }

    [Fact]
    public void FrameReader_GarbageInRandomPieces_YieldsOnlyDelimitedFramesOfAtMost255Characters()
    {
        var random = new Random(232);
        var reader = new FrameReader();
        var taken = 0;
        for (var i = 0; i < 3000; i++)
        {
            var piece = new byte[random.Next(1, 64)];
            for (var j = 0; j < piece.Length; j++)
            {
                piece[j] = random.Next(8) switch { 0 => (byte)'<', 1 => (byte)'>', _ => (byte)random.Next(256) };
            }

            reader.Append(piece);
            reader.PendingChars.Should().BeLessThan(ProtocolLimits.MaxFrameChars);
            while (reader.TryTake(out var result))
            {
                taken++;
                if (result.IsFrame)
                {
                    result.Frame.Length.Should().BeInRange(2, ProtocolLimits.MaxFrameChars);
                    (result.Frame[0], result.Frame[^1]).Should().Be((FrameCodec.StartChar, FrameCodec.EndChar));
                    result.Frame.Skip(1).Should().NotContain(FrameCodec.StartChar);
                    FrameCodec.TryDecode(result.Frame.AsSpan(), out _, out var error).Should().BeFalse($"garbage is not a frame ({error})");
                }
                else
                {
                    result.Error.Should().Be(FrameError.TooLong);
                }
            }
        }

        taken.Should().BeGreaterThan(1000, "the garbage holds many '<' ... '>' runs");
    }
}
