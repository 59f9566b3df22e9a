namespace OperatorPanel.Core.Protocol;

/// <summary>
/// The frame check of protocol v2 (docs/protocol-v2.md, "Frame check"): CRC-16/MCRF4XX over the ASCII codes of the body
/// characters as sent. Polynomial 16#1021 reflected (16#8408), init 16#FFFF, input and output reflected, no final XOR;
/// check("123456789") = 16#6F91 (Greg Cook's CRC catalogue). Computed over characters, not decoded bytes, so the PLC
/// checks a frame before it converts anything. Detects every 1, 2 or 3 flipped bits and every burst of up to 16 bits
/// in a frame of up to 255 characters (proof in the document and in FrameCheckDetectionTests).
/// </summary>
public static class FrameCheck
{
    /// <summary>The register before the first character.</summary>
    public const ushort Initial = 0xFFFF;

    public static ushort Compute(ReadOnlySpan<byte> bodyChars)
    {
        var crc = Initial;
        foreach (var c in bodyChars)
        {
            crc = Update(crc, c);
        }

        return crc;
    }

    /// <summary>
    /// One character without a table (avr-libc <c>_crc_ccitt_update</c>): the form the STL handler runs, byte and
    /// word operations only, 8 bits of the character at once.
    /// </summary>
    public static ushort Update(ushort crc, byte character)
    {
        var d = (byte)(character ^ (byte)crc);
        d ^= (byte)(d << 4);
        return (ushort)(((d << 8) | (crc >> 8)) ^ (d >> 4) ^ (d << 3));
    }
}
