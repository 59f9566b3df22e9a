using System.Collections.Immutable;
using System.Diagnostics.CodeAnalysis;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Projects;

namespace OperatorPanel.Core.Values;

/// <summary>
/// Reads a value the operator typed into the bytes a write carries: big-endian as the S7-200 stores them, or one byte
/// 00/01 for a bit (as <see cref="Writes.WriteRequest.Value"/>). Never throws on bad text: the <see cref="ValueError"/>
/// names the value, the address and the range or notation the address takes.
/// </summary>
public static partial class ValueParser
{
    private static readonly string[] BitOn = ["1", "true", "on"];
    private static readonly string[] BitOff = ["0", "false", "off"];

    public static bool TryParse(
        string? text,
        PlcAddress address,
        DisplayFormat format,
        out ImmutableArray<byte> bytes,
        [NotNullWhen(false)] out ValueError? error)
    {
        bytes = default;
        var input = (text ?? string.Empty).Trim();
        if (input.Length == 0)
        {
            error = new ValueError(ValueErrorKind.Empty, $"{address}: no value given");
            return false;
        }

        if (!format.Fits(address.Width))
        {
            error = new ValueError(ValueErrorKind.FormatDoesNotFit, $"{address}: {DoesNotFit(format, address.Width)}");
            return false;
        }

        var range = new WidthRange(address.Width);
        var parsed = format switch
        {
            DisplayFormat.Bool => ParseBit(input, address, out error),
            DisplayFormat.Float => ParseFloat(input, address, out error),
            DisplayFormat.Ascii => ParseAscii(input, address, range, out error),
            DisplayFormat.Unsigned or DisplayFormat.Signed or DisplayFormat.Hex or DisplayFormat.Binary => ParseInteger(input, address, format, range, out error),
        };
        bytes = parsed ?? default;
        return parsed is not null;
    }

    private static string DoesNotFit(DisplayFormat format, AccessWidth width) => format switch
    {
        DisplayFormat.Bool => $"Bool takes a bit address, not a {new WidthRange(width).Name}",
        DisplayFormat.Float => "a REAL (Float) needs a double word such as VD100",
        DisplayFormat.Unsigned or DisplayFormat.Signed or DisplayFormat.Hex or DisplayFormat.Binary or DisplayFormat.Ascii =>
            $"{format} needs a byte, word or double word, not a bit (a bit takes 0/1, true/false or on/off)",
    };

    private static ImmutableArray<byte>? ParseBit(string input, PlcAddress address, out ValueError? error)
    {
        error = null;
        if (BitOn.Contains(input, StringComparer.OrdinalIgnoreCase))
        {
            return [1];
        }

        if (BitOff.Contains(input, StringComparer.OrdinalIgnoreCase))
        {
            return [0];
        }

        error = new ValueError(ValueErrorKind.Malformed, $"{address}: '{input}' is not a bit value; write 0/1, true/false or on/off");
        return null;
    }

    private static ImmutableArray<byte>? ParseAscii(string input, PlcAddress address, WidthRange range, out ValueError? error)
    {
        error = null;
        var text = IsQuoted(input) ? input[1..^1] : input;
        if (text.Length != range.Bytes)
        {
            error = new ValueError(ValueErrorKind.WrongLength,
                $"{address}: '{text}' has {text.Length} character{(text.Length == 1 ? string.Empty : "s")}; a {range.Name} takes exactly {range.Bytes} ASCII character{(range.Bytes == 1 ? string.Empty : "s")}");
            return null;
        }

        if (text.Any(c => c is < ' ' or > '~'))
        {
            error = new ValueError(ValueErrorKind.NotAscii, $"{address}: '{text}' holds a character outside printable ASCII (space to ~)");
            return null;
        }

        return [.. text.Select(c => (byte)c)];
    }

    private static bool IsQuoted(string input) =>
        input.Length >= 2 && input[0] is '\'' or '"' && input[^1] == input[0];
}
