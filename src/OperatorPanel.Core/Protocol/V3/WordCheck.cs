using System.Buffers.Binary;

namespace OperatorPanel.Core.Protocol.V3;

/// <summary>
/// The frame check of protocol v3 (docs/protocol.md section 1.2): 4 bytes after the covered bytes ('&lt;' through the
/// last byte before the check). The covered bytes, padded with zero bytes to a multiple of 4, are read as big-endian
/// 16-bit units u_0 .. u_n-1. B is a Horner sum over GF(2)[x]/P: for each unit B = (B XOR u) * x; A is the XOR of
/// every unit. The check is A XOR B (2 bytes, high first) then B (2 bytes). (When the covered bytes are an even number,
/// the check lies on unit boundaries and the XOR of all units of the frame, check included, is zero; for an odd number
/// it is not, and nothing relies on it.) Chosen because the PLC computes it with a handful of word operations per double word and
/// no table, and it detects every error of up to 3 bits and every burst of up to 16 bits (proof in the document).
/// </summary>
public static class WordCheck
{
    /// <summary>x^16 + x^5 + x^3 + x^2 + 1 without its x^16 term: a primitive polynomial (x has order 65535).</summary>
    public const ushort Polynomial = 0x002D;

    /// <summary>The check's bytes: A XOR B, then B, each high byte first.</summary>
    public const int Bytes = 4;

    /// <summary>The check of <paramref name="covered"/>: (A XOR B) in the high 16 bits, B in the low 16 bits.</summary>
    public static uint Compute(ReadOnlySpan<byte> covered)
    {
        var (a, b) = Sums(covered);
        return ((uint)(ushort)(a ^ b) << 16) | b;
    }

    /// <summary>Writes the 4 check bytes of <paramref name="covered"/> to <paramref name="destination"/>.</summary>
    public static void Write(ReadOnlySpan<byte> covered, Span<byte> destination) =>
        BinaryPrimitives.WriteUInt32BigEndian(destination, Compute(covered));

    /// <summary>True when <paramref name="frame"/>'s last 4 bytes are the check of the bytes before them.</summary>
    public static bool Matches(ReadOnlySpan<byte> frame) =>
        frame.Length >= Bytes && BinaryPrimitives.ReadUInt32BigEndian(frame[^Bytes..]) == Compute(frame[..^Bytes]);

    /// <summary>B * x modulo x^16 + <see cref="Polynomial"/>: shift left, and fold the bit shifted out back in.</summary>
    public static ushort TimesX(ushort b) => (ushort)((b & 0x8000) != 0 ? (b << 1) ^ Polynomial : b << 1);

    /// <summary>A (the XOR of the units) and B (the Horner sum), padding with zero bytes to a multiple of 4.</summary>
    public static (ushort A, ushort B) Sums(ReadOnlySpan<byte> covered)
    {
        ushort a = 0, b = 0;
        var units = (covered.Length + 3) / 4 * 2;
        for (var k = 0; k < units; k++)
        {
            var high = 2 * k < covered.Length ? covered[2 * k] : 0;
            var low = (2 * k) + 1 < covered.Length ? covered[(2 * k) + 1] : 0;
            var unit = (ushort)((high << 8) | low);
            a ^= unit;
            b = TimesX((ushort)(b ^ unit));
        }

        return (a, b);
    }
}
