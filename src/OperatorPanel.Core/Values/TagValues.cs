using System.Buffers.Binary;
using System.Collections.Immutable;
using System.Diagnostics.CodeAnalysis;
using System.Globalization;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Projects;

namespace OperatorPanel.Core.Values;

/// <summary>
/// A memory cell's value as the operator reads and types it: in the tag's format, scaled to engineering units, with its
/// unit ("55.2 %"), and a typed value checked against the tag's range before it becomes the raw bytes of a write. A tag
/// without scale, range or unit behaves exactly as <see cref="ValueFormatter"/> and <see cref="ValueParser"/>.
/// </summary>
public static class TagValues
{
    /// <summary>True when a scale and a range may be given for <paramref name="format"/>: numbers only.</summary>
    public static bool IsNumeric(DisplayFormat format) => format is DisplayFormat.Unsigned or DisplayFormat.Signed or DisplayFormat.Float;

    /// <summary>"55.2 %": the raw bytes scaled and with the unit; the plain formatted value when the tag has neither.</summary>
    public static string Format(ProjectTag tag, ReadOnlySpan<byte> raw)
    {
        ArgumentNullException.ThrowIfNull(tag);
        return Format(tag.Address, tag.Format, tag.Scale, tag.Unit, raw);
    }

    /// <summary>The same for a value known by its address, format, scale and unit (a recorded value of the historian).</summary>
    public static string Format(PlcAddress address, DisplayFormat format, TagScale? scale, string? unit, ReadOnlySpan<byte> raw)
    {
        var text = scale is not null && IsNumeric(format)
            ? scale.ToValue(RawNumber(format, raw)).ToString("F" + scale.Decimals.ToString(CultureInfo.InvariantCulture), CultureInfo.InvariantCulture)
            : ValueFormatter.Format(raw, address.Width, format);
        return unit is not null ? $"{text} {unit}" : text;
    }

    /// <summary>
    /// The bytes to write for <paramref name="text"/>, typed in the tag's units (a trailing unit is allowed: "55.2 %");
    /// refused with a message naming the symbol when it is no value, outside the tag's range, or outside what the address holds.
    /// </summary>
    public static bool TryParse(ProjectTag tag, string? text, out ImmutableArray<byte> bytes, [NotNullWhen(false)] out ValueError? error)
    {
        ArgumentNullException.ThrowIfNull(tag);
        var input = WithoutUnit((text ?? string.Empty).Trim(), tag.Unit);
        if ((tag.Scale is null && tag.Range is null) || !IsNumeric(tag.Format))
        {
            return ValueParser.TryParse(input, tag.Address, tag.Format, out bytes, out error);
        }

        bytes = default;
        var name = $"{tag.Symbol} ({tag.Address})";
        if (!TagScale.TryNumber(input, out var value))
        {
            error = new ValueError(input.Length == 0 ? ValueErrorKind.Empty : ValueErrorKind.Malformed, input.Length == 0
                ? $"{name}: no value given"
                : $"{name}: '{input}' is not a number{(tag.Unit is { } u ? $" of {u}" : string.Empty)}");
            return false;
        }

        if (tag.Range is { } range && !range.Contains(value))
        {
            error = new ValueError(ValueErrorKind.OutOfRange, $"{name}: {TagScale.Number(value)}{Unit(tag)} is outside its range {range}{Unit(tag)}");
            return false;
        }

        var raw = tag.Scale?.ToRaw(value) ?? value;
        var rawText = tag.Format == DisplayFormat.Float
            ? raw.ToString("R", CultureInfo.InvariantCulture)
            : Math.Round(raw, MidpointRounding.AwayFromZero).ToString("0", CultureInfo.InvariantCulture);
        if (!ValueParser.TryParse(rawText, tag.Address, tag.Format, out bytes, out var rawError))
        {
            error = tag.Scale is null ? rawError : new ValueError(rawError.Kind, $"{name}: {TagScale.Number(value)}{Unit(tag)} is raw {rawText}, which {tag.Address} cannot hold ({rawError.Message})");
            return false;
        }

        error = null;
        return true;
    }

    /// <summary>The raw number of a numeric format's bytes.</summary>
    public static double RawNumber(DisplayFormat format, ReadOnlySpan<byte> raw) => format switch
    {
        DisplayFormat.Signed => ValueFormatter.Signed(raw),
        DisplayFormat.Float => BitConverter.UInt32BitsToSingle(BinaryPrimitives.ReadUInt32BigEndian(raw)),
        _ => ValueFormatter.Unsigned(raw),
    };

    private static string Unit(ProjectTag tag) => tag.Unit is { } unit ? " " + unit : string.Empty;

    private static string WithoutUnit(string text, string? unit) =>
        unit is not null && text.EndsWith(unit, StringComparison.Ordinal) && text.Length > unit.Length ? text[..^unit.Length].TrimEnd() : text;
}
