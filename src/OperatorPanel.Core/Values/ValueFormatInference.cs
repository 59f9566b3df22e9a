using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Projects;

namespace OperatorPanel.Core.Values;

/// <summary>
/// The format a value's own notation implies, for writes typed without one (<c>opanel write VW104=-5</c>): a bit is Bool;
/// 16#/0x is Hex; 2# is Binary; quoted text is Ascii; a '.' or an exponent is Float; a leading '-' is Signed; anything
/// else Unsigned.
/// </summary>
public static class ValueFormatInference
{
    public static DisplayFormat Infer(string? text, AccessWidth width)
    {
        var input = (text ?? string.Empty).Trim();
        if (width == AccessWidth.Bit)
        {
            return DisplayFormat.Bool;
        }

        var unsigned = input.TrimStart('+', '-');
        if (unsigned.StartsWith("16#", StringComparison.Ordinal) || unsigned.StartsWith("0x", StringComparison.OrdinalIgnoreCase))
        {
            return DisplayFormat.Hex;
        }

        if (unsigned.StartsWith("2#", StringComparison.Ordinal))
        {
            return DisplayFormat.Binary;
        }

        if (input.Length >= 2 && input[0] is '\'' or '"' && input[^1] == input[0])
        {
            return DisplayFormat.Ascii;
        }

        if (input.Contains('.', StringComparison.Ordinal) || input.Contains('e', StringComparison.OrdinalIgnoreCase))
        {
            return DisplayFormat.Float;
        }

        return input.StartsWith('-') ? DisplayFormat.Signed : DisplayFormat.Unsigned;
    }
}
