using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Core.Tests.Protocol;

/// <summary>
/// The detection claim of docs/protocol-v2.md ("Frame check", "Why"): every error of 1, 2 or 3 flipped bits and every
/// burst of up to 16 bits in a frame of up to 255 characters is detected. First the algebra behind it, computed here
/// over GF(2); then exhaustively, every 1-, 2- and 3-bit flip of short real frames, received the way the panel
/// receives (<see cref="FrameReader"/>, then <see cref="FrameCodec"/>).
/// </summary>
public sealed class FrameCheckDetectionTests
{
    /// <summary>x^16 + x^12 + x^5 + 1: CRC-16/MCRF4XX's generator (16#1021 with the x^16 term).</summary>
    private const uint Generator = 0x11021;

    /// <summary>2^15 - 1 = 7 x 31 x 151: the order x has modulo a primitive polynomial of degree 15.</summary>
    private const int PrimitiveOrder = 32767;

    [Fact]
    public void Generator_IsXPlusOneTimesAPrimitivePolynomialOfDegree15()
    {
        var (quotient, remainder) = Divide(Generator, 0b11);

        remainder.Should().Be(0, "g(1) = 0: x + 1 divides g, so every odd number of flipped bits is detected");
        Degree(quotient).Should().Be(15);
        PowerOfX(PrimitiveOrder, quotient).Should().Be(1u);
        foreach (var prime in new[] { 7, 31, 151 })
        {
            PowerOfX(PrimitiveOrder / prime, quotient).Should().NotBe(1u, $"the order of x is not a divisor 32767/{prime}");
        }
    }

    [Fact]
    public void LongestFrame_IsShorterThanThePeriod_SoEveryTwoBitErrorIsDetected()
    {
        // Two flips d bits apart leave x^d + 1; the primitive factor divides it only when 32767 divides d. The codeword
        // is the body's data bits followed by the 16 check bits (the check characters' low nibbles).
        var codewordBits = (8 * 2 * ProtocolLimits.MaxBodyBytes) + 16;

        codewordBits.Should().BeLessThan(PrimitiveOrder);
        var (primitive, _) = Divide(Generator, 0b11);
        Enumerable.Range(1, codewordBits).Should().OnlyContain(d => PowerOfX(d, primitive) != 1u, "x^d + 1 is not a multiple for any d < 32767");
    }

    [Fact]
    public void EveryBurstUpTo16Bits_LeavesANonZeroRemainder()
    {
        // A burst is x^i b(x) with b(0) = 1 and degree at most 15; g has constant term 1, so g divides it only if g
        // divides b, which has the lower degree.
        Enumerable.Range(1, 0xFFFF).Where(b => (b & 1) == 1).Should().OnlyContain(b => Divide((uint)b, Generator).Remainder != 0);
    }

    [Theory]
    [MemberData(nameof(ShortFrames))]
    public void EveryOneTwoAndThreeBitFlip_OfARealFrame_IsNeverAccepted(string name, byte[] frame)
    {
        var bits = 8 * frame.Length;
        var reader = new FrameReader();
        var accepted = new List<string>();
        var patterns = 0;
        for (var a = 0; a < bits; a++)
        {
            for (var b = a; b < bits; b++)
            {
                for (var c = b; c < bits; c++)
                {
                    // a == b == c is one flip, b == c two (a, b), all distinct three.
                    if (a == b && b != c)
                    {
                        continue;
                    }

                    var flipped = (byte[])frame.Clone();
                    Flip(flipped, a);
                    if (b != a)
                    {
                        Flip(flipped, b);
                    }

                    if (c != b)
                    {
                        Flip(flipped, c);
                    }

                    patterns++;
                    if (Accepts(reader, flipped))
                    {
                        accepted.Add($"{a},{b},{c}");
                    }
                }
            }
        }

        patterns.Should().Be(bits + (bits * (bits - 1) / 2) + (bits * (bits - 1) * (bits - 2) / 6));
        accepted.Should().BeEmpty($"frame {name}: no flipped copy may pass as a valid frame");
    }

    public static TheoryData<string, byte[]> ShortFrames() => new()
    {
        { "IDENTIFY request", RequestCodec.Encode(new IdentifyRequest(new Station(1), 0x07)) },
        { "READ CHANGES request", RequestCodec.Encode(new ReadChangesRequest(new Station(1), 0x17, 1, Full: false)) },
        { "READ CHANGES idle reply", ResponseCodec.Encode(ReadChangesResponse.Pairs(new Station(1), 0x17, []) with { RequestCheck = 0x84D5 }) },
    };

    /// <summary>True when any frame the panel would cut from <paramref name="chars"/> decodes.</summary>
    private static bool Accepts(FrameReader reader, byte[] chars)
    {
        reader.Reset();
        reader.Append(chars);
        while (reader.TryTake(out var result))
        {
            if (result.IsFrame && FrameCodec.TryDecode(result.Frame.AsSpan(), out _, out _))
            {
                return true;
            }
        }

        return false;
    }

    private static void Flip(byte[] chars, int bit) => chars[bit / 8] ^= (byte)(1 << (bit % 8));

    private static int Degree(uint polynomial) => 31 - int.LeadingZeroCount((int)polynomial);

    /// <summary>Polynomial division over GF(2), coefficients as bits.</summary>
    private static (uint Quotient, uint Remainder) Divide(uint dividend, uint divisor)
    {
        var quotient = 0u;
        var d = Degree(divisor);
        while (dividend != 0 && Degree(dividend) >= d)
        {
            var shift = Degree(dividend) - d;
            quotient |= 1u << shift;
            dividend ^= divisor << shift;
        }

        return (quotient, dividend);
    }

    /// <summary>x^n mod <paramref name="modulus"/> by square and multiply.</summary>
    private static uint PowerOfX(int n, uint modulus)
    {
        var result = 1u;
        var square = Divide(0b10, modulus).Remainder;
        for (; n > 0; n >>= 1)
        {
            if ((n & 1) == 1)
            {
                result = MultiplyMod(result, square, modulus);
            }

            square = MultiplyMod(square, square, modulus);
        }

        return result;
    }

    private static uint MultiplyMod(uint a, uint b, uint modulus)
    {
        var product = 0ul;
        for (var i = 0; i < 32; i++)
        {
            if ((b & (1u << i)) != 0)
            {
                product ^= (ulong)a << i;
            }
        }

        var d = Degree(modulus);
        for (var bit = 63; bit >= d; bit--)
        {
            if ((product & (1ul << bit)) != 0)
            {
                product ^= (ulong)modulus << (bit - d);
            }
        }

        return (uint)product;
    }
}
