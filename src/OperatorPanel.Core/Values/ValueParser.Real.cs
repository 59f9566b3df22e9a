using System.Buffers.Binary;
using System.Collections.Immutable;
using System.Globalization;
using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Core.Values;

/// <summary>
/// REAL numbers: IEEE 754 single precision, whose range the S7-200 manual gives as +1.175495E-38 to +3.402823E+38 and
/// -1.175495E-38 to -3.402823E+38, and 0 (C233-01 p. 5-4; docs/sources/s7200-facts.md section 15). A number the REAL
/// holds only approximately (0.1) is written as the nearest REAL, and the read-back is compared with that REAL's bytes;
/// a number it cannot hold at all is refused before anything is sent: too large, not a number, or so close to 0 that
/// it would be stored as 0 or as a denormal outside the manual's range (1.5e-50 would be written as 0, read back as 0
/// and look confirmed).
/// </summary>
public static partial class ValueParser
{
    /// <summary>The manual's range, in the words the messages use.</summary>
    private const string RealRange = "a REAL holds 0 and numbers from ±1.175495E-38 to ±3.402823E+38";

    private static ImmutableArray<byte>? ParseFloat(string input, PlcAddress address, out ValueError? error)
    {
        error = null;
        if (!double.TryParse(input, NumberStyles.Float, CultureInfo.InvariantCulture, out var number))
        {
            error = new ValueError(ValueErrorKind.Malformed, $"{address}: '{input}' is not a REAL number; write e.g. 12.5, -0.25 or 1.5e3");
            return null;
        }

        if (double.IsNaN(number) || (double.IsInfinity(number) && !input.Any(char.IsAsciiDigit)))
        {
            error = new ValueError(ValueErrorKind.NotFinite, $"{address}: {input} is not a number a REAL can hold ({RealRange})");
            return null;
        }

        // Rounding to single precision decides: 3.4028235E+38 (the largest REAL, as the manual rounds it: 3.402823E+38)
        // stays, 1e39 (and 1e400, which is infinite already as a double) becomes infinite.
        var single = (float)number;
        if (float.IsInfinity(single))
        {
            error = new ValueError(ValueErrorKind.OutOfRange, $"{address}: {input} is too large for a REAL ({RealRange}); write a number inside that range");
            return null;
        }

        // 1e-400 reads as a double 0 already: the typed digits say whether the operator meant 0.
        if (single == 0 ? number != 0 || HasNonZeroDigit(input) : !float.IsNormal(single))
        {
            var stored = single.ToString(CultureInfo.InvariantCulture);
            error = new ValueError(ValueErrorKind.OutOfRange,
                $"{address}: {input} is too close to 0 for a REAL ({RealRange}): it would be stored as {stored}; write 0 or a number inside that range");
            return null;
        }

        var bytes = new byte[4];
        BinaryPrimitives.WriteUInt32BigEndian(bytes, BitConverter.SingleToUInt32Bits(single));
        return [.. bytes];
    }

    /// <summary>True when the digits before the exponent are not all 0: "1e-400" means a number, "0.0e5" means 0.</summary>
    private static bool HasNonZeroDigit(string input)
    {
        var exponent = input.IndexOfAny(['e', 'E']);
        return (exponent < 0 ? input : input[..exponent]).Any(c => c is >= '1' and <= '9');
    }
}
