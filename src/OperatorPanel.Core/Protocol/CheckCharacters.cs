namespace OperatorPanel.Core.Protocol;

/// <summary>
/// The four characters that carry a 16-bit check after the body: 16#60 + nibble, least significant nibble first
/// ("`abcdefghijklmno"). Never '&lt;', '&gt;' or a hex digit, and their low 4 bits are the CRC bits in wire order, so
/// body and check form one CRC codeword on the line (docs/protocol-v2.md, "Why").
/// </summary>
public static class CheckCharacters
{
    /// <summary>Characters a check takes.</summary>
    public const int Count = 4;

    /// <summary>The character of nibble 0.</summary>
    public const byte Base = 0x60;

    public static void Write(ushort check, Span<byte> target)
    {
        for (var i = 0; i < Count; i++)
        {
            target[i] = (byte)(Base + ((check >> (4 * i)) & 0x0F));
        }
    }

    /// <summary>False when a character lies outside 16#60-16#6F.</summary>
    public static bool TryRead(ReadOnlySpan<byte> characters, out ushort check)
    {
        check = 0;
        if (characters.Length != Count)
        {
            return false;
        }

        for (var i = 0; i < Count; i++)
        {
            var c = characters[i];
            if (c is < Base or > Base + 0x0F)
            {
                return false;
            }

            check |= (ushort)((c - Base) << (4 * i));
        }

        return true;
    }
}
