using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Projects;

namespace OperatorPanel.Core.Values;

/// <summary>Whole numbers: Unsigned, Signed, Hex and Binary, each with the ranges of the address's width.</summary>
public static partial class ValueParser
{
    private static ImmutableArray<byte>? ParseInteger(string input, PlcAddress address, DisplayFormat format, WidthRange range, out ValueError? error)
    {
        error = null;
        var defaultRadix = format switch
        {
            DisplayFormat.Hex => 16,
            DisplayFormat.Binary => 2,
            DisplayFormat.Unsigned or DisplayFormat.Signed or DisplayFormat.Bool or DisplayFormat.Float or DisplayFormat.Ascii => 10,
        };
        if (!IntegerText.TryRead(input, defaultRadix, out var number))
        {
            error = new ValueError(ValueErrorKind.Malformed, $"{address}: '{input}' is not {Notation(format)}");
            return null;
        }

        // A signed decimal takes INT/DINT's range; a bit pattern (16#, 2#, or an unsigned format) the unsigned range.
        var signed = format == DisplayFormat.Signed && (number.Radix == 10 || number.Negative);
        ulong? bits = signed ? SignedBits(number, range) : UnsignedBits(number, range);
        if (bits is not { } value)
        {
            error = new ValueError(ValueErrorKind.OutOfRange, $"{address}: {input} is outside {Allowed(format, range, signed)}");
            return null;
        }

        return [.. range.BigEndian(value)];
    }

    private static ulong? UnsignedBits(IntegerText number, WidthRange range) =>
        number.Negative && number.Magnitude != 0 || number.Magnitude > range.UnsignedMax ? null : number.Magnitude;

    private static ulong? SignedBits(IntegerText number, WidthRange range)
    {
        var limit = number.Negative ? (ulong)-range.SignedMin : (ulong)range.SignedMax;
        if (number.Magnitude > limit)
        {
            return null;
        }

        var value = number.Negative ? -(long)number.Magnitude : (long)number.Magnitude;
        return (ulong)value & range.UnsignedMax;
    }

    private static string Allowed(DisplayFormat format, WidthRange range, bool signed) => signed
        ? $"{range.SignedText}, the range of a signed {range.Name}"
        : format switch
        {
            DisplayFormat.Hex => $"{range.HexText}, the range of a {range.Name}",
            DisplayFormat.Binary => $"{range.BinaryText}, the range of a {range.Name}",
            DisplayFormat.Unsigned or DisplayFormat.Signed or DisplayFormat.Bool or DisplayFormat.Float or DisplayFormat.Ascii =>
                $"{range.UnsignedText}, the range of an unsigned {range.Name} (a signed {range.Name} takes {range.SignedText})",
        };

    private static string Notation(DisplayFormat format) => format switch
    {
        DisplayFormat.Hex => "a hexadecimal number; write e.g. 16#FF or 0xFF",
        DisplayFormat.Binary => "a binary number; write e.g. 2#1010 or 2#0000_1010",
        DisplayFormat.Unsigned or DisplayFormat.Signed or DisplayFormat.Bool or DisplayFormat.Float or DisplayFormat.Ascii =>
            "a whole number; write e.g. 42, -7, 16#2A or 2#1010",
    };
}
