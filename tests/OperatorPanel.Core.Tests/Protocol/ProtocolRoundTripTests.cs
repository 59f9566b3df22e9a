using FluentAssertions.Equivalency;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Core.Tests.Protocol;

public sealed class ProtocolRoundTripTests
{
    private const int Cases = 5000;

    [Fact]
    public void Request_EncodeThenParse_GivesTheSameRequest()
    {
        var rng = new Random(20240601);
        for (var i = 0; i < Cases; i++)
        {
            var request = RandomMessages.Request(rng);
            var chars = RequestCodec.Encode(request);

            chars.Length.Should().BeLessThanOrEqualTo(ProtocolLimits.MaxFrameChars);
            FrameCodec.TryDecode(chars, out var frame, out var frameError).Should().BeTrue($"{request} must decode ({frameError})");
            RequestCodec.TryParse(frame, null, out var parsed, out var error).Should().BeTrue($"{request} must parse ({error})");
            parsed.Should().BeEquivalentTo(request, ByMembers);
        }
    }

    [Fact]
    public void Response_EncodeThenDecodeAgainstItsRequest_GivesTheSameResponse()
    {
        var rng = new Random(7);
        for (var i = 0; i < Cases; i++)
        {
            var request = RandomMessages.Request(rng);
            var response = RandomMessages.ResponseTo(rng, request);
            var chars = ResponseCodec.Encode(response);

            ResponseCodec.TryDecode(chars, request, out var decoded, out var error).Should().BeTrue($"{response} must decode ({error})");
            decoded.Should().BeEquivalentTo(response, ByMembers);
        }
    }

    [Fact]
    public void FrameReader_FramesInRandomPiecesWithNoise_YieldsEveryFrameInOrderAndCountsTheNoise()
    {
        var rng = new Random(42);
        var stream = new List<byte>();
        var expected = new List<(byte[] Frame, int Noise)>();
        for (var i = 0; i < Cases; i++)
        {
            var noise = Noise(rng, rng.Next(4) == 0 ? rng.Next(1, 20) : 0);
            var request = RandomMessages.Request(rng);
            var frame = rng.Next(2) == 0 ? RequestCodec.Encode(request) : ResponseCodec.Encode(RandomMessages.ResponseTo(rng, request));
            stream.AddRange(noise);
            stream.AddRange(frame);
            expected.Add((frame, noise.Length));
        }

        var reader = new FrameReader();
        var results = new List<FrameReadResult>();
        var all = stream.ToArray();
        for (var at = 0; at < all.Length;)
        {
            var piece = Math.Min(rng.Next(1, 40), all.Length - at);
            reader.Append(all.AsSpan(at, piece));
            at += piece;
            while (reader.TryTake(out var result))
            {
                results.Add(result);
            }
        }

        results.Should().HaveCount(expected.Count);
        for (var i = 0; i < expected.Count; i++)
        {
            results[i].Error.Should().Be(FrameError.None);
            results[i].Frame.Should().Equal(expected[i].Frame);
            results[i].SkippedBytes.Should().Be(expected[i].Noise);
        }
    }

    private static EquivalencyAssertionOptions<T> ByMembers<T>(EquivalencyAssertionOptions<T> options) =>
        options.ComparingRecordsByMembers().RespectingRuntimeTypes();

    /// <summary>Line noise: anything but '&lt;' (a '&gt;' or a hex digit outside a frame is noise too).</summary>
    private static byte[] Noise(Random rng, int count)
    {
        var noise = RandomMessages.Bytes(rng, count).ToArray();
        for (var i = 0; i < noise.Length; i++)
        {
            if (noise[i] == FrameCodec.StartChar)
            {
                noise[i] = 0x00;
            }
        }

        return noise;
    }
}
