using System.Diagnostics.CodeAnalysis;

namespace OperatorPanel.Core.Addressing;

public readonly partial record struct PlcAddress
{
    /// <summary>
    /// Reads an address written as in STL (case-insensitive, surrounding blanks ignored). Never throws:
    /// a refusal comes back as an <see cref="AddressError"/> naming what was wrong.
    /// </summary>
    public static bool TryParse(
        [NotNullWhen(true)] string? text,
        out PlcAddress address,
        [NotNullWhen(false)] out AddressError? error)
    {
        address = default;
        var input = (text ?? string.Empty).Trim();
        if (input.Length == 0)
        {
            error = new AddressError(AddressErrorKind.Empty, "address is empty");
            return false;
        }

        var upper = input.ToUpperInvariant();
        if (!TryArea(upper, input, out var area, out var rest, out error))
        {
            return false;
        }

        if (AreaSyntax.IsNumbered(area))
        {
            return TryNumbered(input, area, rest, out address, out error);
        }

        var width = AccessWidth.Bit;
        if (rest.Length > 0 && WidthOf(rest[0]) is { } letterWidth)
        {
            width = letterWidth;
            rest = rest[1..];
        }

        if (!AreaSyntax.Allows(area, width))
        {
            error = WidthRefusal(input, area);
            return false;
        }

        var digits = LeadingDigits(rest);
        if (digits.Length == 0)
        {
            error = new AddressError(AddressErrorKind.MissingByteNumber, $"'{input}': a byte number must follow '{AreaSyntax.Prefix(area)}{width.Letter()}'");
            return false;
        }

        if (!TryNumber(digits, out var byteOffset))
        {
            error = new AddressError(AddressErrorKind.ByteNumberTooLarge, $"'{input}': byte number {digits} is larger than {MaxByteOffset}");
            return false;
        }

        rest = rest[digits.Length..];
        return width == AccessWidth.Bit
            ? TryBitPart(input, area, byteOffset, rest, out address, out error)
            : TryWordPart(input, area, byteOffset, width, rest, out address, out error);
    }

    private static bool TryArea(string upper, string input, out MemoryArea area, out string rest, [NotNullWhen(false)] out AddressError? error)
    {
        foreach (var (prefix, candidate) in AreaSyntax.Parsed)
        {
            if (upper.StartsWith(prefix, StringComparison.Ordinal))
            {
                area = candidate;
                rest = upper[prefix.Length..];
                error = null;
                return true;
            }
        }

        area = default;
        rest = string.Empty;
        foreach (var (prefix, name) in AreaSyntax.Unsupported)
        {
            if (upper.StartsWith(prefix, StringComparison.Ordinal))
            {
                error = new AddressError(AddressErrorKind.UnknownArea, name.Contains(';', StringComparison.Ordinal)
                    ? $"'{input}': {name}: copy what you need to V in the PLC program and watch that"
                    : $"'{input}': {name}: {LinkAreas.NotServed(prefix, input.Trim())}");
                return false;
            }
        }

        error = new AddressError(AddressErrorKind.UnknownArea, $"'{input}': unknown memory area; an address starts with I, Q, M, V, SM, S, AIW, AQW, T or C");
        return false;
    }

    private static bool TryBitPart(string input, MemoryArea area, int byteOffset, string rest, out PlcAddress address, [NotNullWhen(false)] out AddressError? error)
    {
        address = default;
        var prefix = AreaSyntax.Prefix(area);
        if (rest.Length == 0)
        {
            error = new AddressError(AddressErrorKind.MissingBitNumber, $"'{input}': a bit address needs a bit number ({prefix}{byteOffset}.0) or a width letter ({prefix}B{byteOffset})");
            return false;
        }

        if (rest[0] != '.')
        {
            error = Trailing(input, rest);
            return false;
        }

        var bitDigits = LeadingDigits(rest[1..]);
        if (bitDigits.Length == 0)
        {
            error = new AddressError(AddressErrorKind.MissingBitNumber, $"'{input}': the bit number after '.' is missing (0-7)");
            return false;
        }

        if (bitDigits.Length + 1 < rest.Length)
        {
            error = Trailing(input, rest[(bitDigits.Length + 1)..]);
            return false;
        }

        if (bitDigits.Length > 1 || bitDigits[0] > '7')
        {
            error = new AddressError(AddressErrorKind.BitOutOfRange, $"'{input}': bit number {bitDigits} is outside 0-7");
            return false;
        }

        address = new PlcAddress(area, byteOffset, bitDigits[0] - '0', AccessWidth.Bit);
        error = null;
        return true;
    }

    private static bool TryWordPart(string input, MemoryArea area, int byteOffset, AccessWidth width, string rest, out PlcAddress address, [NotNullWhen(false)] out AddressError? error)
    {
        address = default;
        if (rest.StartsWith('.'))
        {
            error = new AddressError(AddressErrorKind.UnexpectedBitNumber, $"'{input}': a {WidthName(width)} address takes no bit number; write {AreaSyntax.Prefix(area)}{byteOffset}{rest} for a bit");
            return false;
        }

        if (rest.Length > 0)
        {
            error = Trailing(input, rest);
            return false;
        }

        if (AreaSyntax.IsAnalog(area) && byteOffset % 2 != 0)
        {
            error = new AddressError(AddressErrorKind.OddAnalogOffset, $"'{input}': analog words start at even byte numbers ({AreaSyntax.Prefix(area)}W{byteOffset - 1} or {AreaSyntax.Prefix(area)}W{byteOffset + 1})");
            return false;
        }

        address = new PlcAddress(area, byteOffset, null, width);
        error = null;
        return true;
    }

    /// <summary>
    /// T37 or C5: the timer's or counter's current value, a signed word as the CPU holds it. The panel has no form for
    /// the timer or counter bit: over PPI it comes in a status byte whose layout no source documents (docs/ppi.md
    /// section 6), so the program copies the bit to M or V when the panel is to show it.
    /// </summary>
    private static bool TryNumbered(string input, MemoryArea area, string rest, out PlcAddress address, [NotNullWhen(false)] out AddressError? error)
    {
        address = default;
        var prefix = AreaSyntax.Prefix(area);
        var what = area == MemoryArea.T ? "timer" : "counter";
        var digits = LeadingDigits(rest);
        if (digits.Length == 0)
        {
            error = new AddressError(AddressErrorKind.MissingByteNumber, $"'{input}': a {what} is written {prefix} and its number ({prefix}{(area == MemoryArea.T ? 37 : 5)}), which reads its current value");
            return false;
        }

        if (!TryNumber(digits, out var number))
        {
            error = new AddressError(AddressErrorKind.ByteNumberTooLarge, $"'{input}': {what} number {digits} is larger than {MaxByteOffset}");
            return false;
        }

        if (digits.Length < rest.Length)
        {
            error = rest[digits.Length] == '.'
                ? new AddressError(AddressErrorKind.UnexpectedBitNumber, $"'{input}': {prefix}{number} is the {what}'s current value and takes no bit number; the panel does not read {what} bits (copy the bit to M or V in the PLC program)")
                : Trailing(input, rest[digits.Length..]);
            return false;
        }

        address = new PlcAddress(area, number, null, AccessWidth.Word);
        error = null;
        return true;
    }

    /// <summary>Only the analog areas restrict widths (words only); every other parsed area takes them all.</summary>
    private static AddressError WidthRefusal(string input, MemoryArea area)
    {
        var prefix = AreaSyntax.Prefix(area);
        var kind = area == MemoryArea.AI ? "inputs" : "outputs";
        return new AddressError(AddressErrorKind.WidthNotAllowed, $"'{input}': analog {kind} are addressed as words only ({prefix}W0, {prefix}W2, ...)");
    }

    private static string WidthName(AccessWidth width) => width switch
    {
        AccessWidth.Byte => "byte",
        AccessWidth.Word => "word",
        AccessWidth.DoubleWord => "double word",
        AccessWidth.Bit => throw new ArgumentOutOfRangeException(nameof(width), width, null),
    };

    private static AddressError Trailing(string input, string rest) =>
        new(AddressErrorKind.TrailingText, $"'{input}': unexpected '{rest}' after the address");

    private static AccessWidth? WidthOf(char letter) => letter switch
    {
        'B' => AccessWidth.Byte,
        'W' => AccessWidth.Word,
        'D' => AccessWidth.DoubleWord,
        _ => null,
    };

    private static string LeadingDigits(string text)
    {
        var count = 0;
        while (count < text.Length && char.IsAsciiDigit(text[count]))
        {
            count++;
        }

        return text[..count];
    }

    private static bool TryNumber(string digits, out int value)
    {
        value = 0;
        foreach (var digit in digits)
        {
            value = (value * 10) + (digit - '0');
            if (value > MaxByteOffset)
            {
                return false;
            }
        }

        return true;
    }
}
