namespace OperatorPanel.Core.Values;

/// <summary>
/// A whole number as typed: optional sign, then STL notation 16#FF or 2#1010 (the manual's constants), C notation
/// 0xFF, or digits in the caller's default radix. Underscores group digits (2#0000_1010). Magnitudes beyond
/// <see cref="ulong.MaxValue"/> saturate, which every range check then refuses.
/// </summary>
internal readonly record struct IntegerText(bool Negative, ulong Magnitude, int Radix)
{
    public static bool TryRead(string text, int defaultRadix, out IntegerText value)
    {
        value = default;
        var rest = text.AsSpan();
        var negative = false;
        if (rest.Length > 0 && rest[0] is '+' or '-')
        {
            negative = rest[0] == '-';
            rest = rest[1..];
        }

        var radix = defaultRadix;
        if (rest.StartsWith("16#") || rest.StartsWith("0x", StringComparison.OrdinalIgnoreCase))
        {
            radix = 16;
            rest = rest[(rest[0] == '1' ? 3 : 2)..];
        }
        else if (rest.StartsWith("2#"))
        {
            radix = 2;
            rest = rest[2..];
        }

        if (rest.IsEmpty || rest[0] == '_' || rest[^1] == '_')
        {
            return false;
        }

        ulong magnitude = 0;
        foreach (var c in rest)
        {
            if (c == '_' && radix != 10)
            {
                continue;
            }

            var digit = DigitValue(c);
            if (digit < 0 || digit >= radix)
            {
                return false;
            }

            magnitude = magnitude > (ulong.MaxValue - (ulong)digit) / (ulong)radix ? ulong.MaxValue : (magnitude * (ulong)radix) + (ulong)digit;
        }

        value = new IntegerText(negative, magnitude, radix);
        return true;
    }

    private static int DigitValue(char c) => c switch
    {
        >= '0' and <= '9' => c - '0',
        >= 'a' and <= 'f' => c - 'a' + 10,
        >= 'A' and <= 'F' => c - 'A' + 10,
        _ => -1,
    };
}
