using System.Diagnostics.CodeAnalysis;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Projects;

namespace OperatorPanel.Cli.Commands;

/// <summary>
/// The ":FORMAT" of an <c>opanel read</c> address (VD16:real), in the words of <c>opanel stl run --print</c> and of the
/// project's tag formats: a REAL written with <c>opanel write VD16=12.5</c> reads back as 12.5, not as 1095237632.
/// </summary>
internal static class ReadFormats
{
    private static readonly Dictionary<string, DisplayFormat> Words = new(StringComparer.OrdinalIgnoreCase)
    {
        ["real"] = DisplayFormat.Float,
        ["float"] = DisplayFormat.Float,
        ["signed"] = DisplayFormat.Signed,
        ["unsigned"] = DisplayFormat.Unsigned,
        ["hex"] = DisplayFormat.Hex,
        ["binary"] = DisplayFormat.Binary,
        ["ascii"] = DisplayFormat.Ascii,
    };

    public static bool TrySplit(string text, out string address, out DisplayFormat? format, [NotNullWhen(false)] out string? error)
    {
        var colon = text.IndexOf(':', StringComparison.Ordinal);
        (address, format, error) = (colon < 0 ? text : text[..colon], null, null);
        if (colon < 0)
        {
            return true;
        }

        if (!Words.TryGetValue(text[(colon + 1)..], out var found))
        {
            error = $"'{text}': unknown format '{text[(colon + 1)..]}'; use real, signed, unsigned, hex, binary or ascii";
            return false;
        }

        format = found;
        return true;
    }

    public static bool TryCheck(PlcAddress address, DisplayFormat? format, string text, [NotNullWhen(false)] out string? error)
    {
        error = format is { } f && !f.Fits(address.Width)
            ? f == DisplayFormat.Float
                ? $"'{text}': a REAL needs a double word such as VD100"
                : $"'{text}': a bit is shown as 0/1; formats are for bytes, words and double words"
            : null;
        return error is null;
    }
}
