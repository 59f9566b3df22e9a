using OperatorPanel.Core.Protocol.V3;

namespace OperatorPanel.Core.Tests.Protocol;

/// <summary>
/// docs/protocol.md section 1.4's promise for protocol v3's WordCheck, proved by computation on the longest frames (255
/// bytes; the four lengths 252-255 cover the four paddings, so every shorter frame is the tail of one of them): every
/// error of 1, 2 or 3 bits and every burst of up to 16 bits, in both bit orders, is detected. The check is linear over
/// GF(2) (XOR and a polynomial residue, both from zero), so a frame with error e = (e_covered, e_check) passes exactly
/// when Compute(e_covered) = e_check: the error's syndrome Compute(e_covered) XOR e_check is 0. The syndromes of the
/// single bits are computed once; every error is then the XOR of its bits' syndromes.
/// </summary>
public sealed class WordCheckDetectionTests
{
    public static TheoryData<int> FrameLengths => [252, 253, 254, 255];

    [Fact]
    public void Check_IsLinear_TheSyndromeOfTwoErrorsIsTheXorOfTheirs()
    {
        var random = new Random(7);
        for (var trial = 0; trial < 200; trial++)
        {
            var length = random.Next(4, 252);
            var x = new byte[length];
            var y = new byte[length];
            random.NextBytes(x);
            random.NextBytes(y);
            var xy = x.Zip(y, (p, q) => (byte)(p ^ q)).ToArray();

            WordCheck.Compute(xy).Should().Be(WordCheck.Compute(x) ^ WordCheck.Compute(y));
        }
    }

    [Theory]
    [MemberData(nameof(FrameLengths))]
    public void EveryOneTwoAndThreeBitError_IsDetected(int frameLength)
    {
        var syndromes = Syndromes(frameLength, lowBitFirst: true);
        var index = new Dictionary<uint, int>(syndromes.Length);
        for (var i = 0; i < syndromes.Length; i++)
        {
            syndromes[i].Should().NotBe(0u, $"bit {i} alone");
            index.TryAdd(syndromes[i], i).Should().BeTrue($"bit {i} and bit {index.GetValueOrDefault(syndromes[i])} together");
        }

        var undetected = 0L;
        for (var i = 0; i < syndromes.Length; i++)
        {
            for (var j = i + 1; j < syndromes.Length; j++)
            {
                // A third bit k completes an undetected error when its syndrome equals s_i XOR s_j (k is neither i nor j,
                // since s_i XOR s_j differs from both: every syndrome is non-zero).
                if (index.ContainsKey(syndromes[i] ^ syndromes[j]))
                {
                    undetected++;
                }
            }
        }

        undetected.Should().Be(0, $"every 3-bit error of a {frameLength}-byte frame");
    }

    [Theory]
    [MemberData(nameof(FrameLengths))]
    public void EveryBurstUpTo16Bits_InEitherBitOrder_IsDetected(int frameLength)
    {
        foreach (var lowBitFirst in new[] { true, false })
        {
            var syndromes = Syndromes(frameLength, lowBitFirst);
            for (var start = 0; start < syndromes.Length; start++)
            {
                // The burst's first bit is `start`; any of the next 15 bits may be in error too (a Gray code walks all 2^15).
                var inner = Math.Min(15, syndromes.Length - start - 1);
                var syndrome = syndromes[start];
                syndrome.Should().NotBe(0u);
                for (var step = 1; step < 1 << inner; step++)
                {
                    syndrome ^= syndromes[start + 1 + System.Numerics.BitOperations.TrailingZeroCount(step)];
                    if (syndrome == 0)
                    {
                        Assert.Fail($"a burst from bit {start} ({(lowBitFirst ? "low" : "high")} bit first) of a {frameLength}-byte frame passes the check");
                    }
                }
            }
        }
    }

    /// <summary>
    /// The syndrome of each bit of a frame of <paramref name="frameLength"/> bytes (LEN - 4 covered bytes, then the 4
    /// check bytes), in wire order: byte by byte, within a byte the low bit first (as a UART sends it) or the high bit.
    /// </summary>
    private static uint[] Syndromes(int frameLength, bool lowBitFirst)
    {
        var covered = frameLength - WordCheck.Bytes;
        var result = new uint[frameLength * 8];
        var unit = new byte[covered];
        for (var bit = 0; bit < result.Length; bit++)
        {
            var (byteIndex, bitInByte) = (bit / 8, lowBitFirst ? bit % 8 : 7 - (bit % 8));
            if (byteIndex < covered)
            {
                unit[byteIndex] = (byte)(1 << bitInByte);
                result[bit] = WordCheck.Compute(unit);
                unit[byteIndex] = 0;
            }
            else
            {
                // A flipped check bit: the check is big-endian, its first byte the high one.
                result[bit] = 1u << ((8 * (WordCheck.Bytes - 1 - (byteIndex - covered))) + bitInByte);
            }
        }

        return result;
    }
}
