using OperatorPanel.Cli.Link;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Messages;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Values;

namespace OperatorPanel.Cli.Commands;

/// <summary>
/// One address as <c>opanel read</c> prints it (text and JSON share this shape). Shown is the value in the format asked
/// for with ADDR:FORMAT (VD16:real -> 12.5), or for a symbol read with --project in its tag's format, scaled and with
/// its unit (TankLevel -> 55.2 %); AIW, AQW, T and C signed (C5 -> -7); null otherwise; the text prints it in place of
/// the unsigned value, and the symbol last.
/// </summary>
internal sealed record ReadValueView(string Address, ulong? Value, string? Hex, string Quality, string? Error, string? Shown = null, string? Symbol = null)
{
    public static ReadValueView From(PlcAddress address, PolledValue? value, DisplayFormat? format = null) =>
        From(new ArgumentTarget(address, null, null, BySymbol: false), value, format);

    public static ReadValueView From(ArgumentTarget target, PolledValue? value, DisplayFormat? format = null)
    {
        var address = target.Address;
        if (value is not { HasValue: true })
        {
            return new ReadValueView(address.ToString(), null, null, "bad", value?.Error ?? "not read", Symbol: target.Symbol);
        }

        var raw = value.Raw.AsSpan();
        var hex = address.Width == AccessWidth.Bit ? null : ValueFormatter.Hex(raw);
        // Analog words and timer and counter current values are signed integers in the CPU: shown signed unless asked otherwise.
        format ??= DisplayFormats.DefaultFor(address) == DisplayFormat.Signed && !target.BySymbol ? DisplayFormat.Signed : null;
        var shown = format is { } f ? ValueFormatter.Format(raw, address.Width, f)
            : target is { BySymbol: true, Tag: { } tag } ? TagValues.Format(tag, raw)
            : null;
        return new ReadValueView(address.ToString(), ValueFormatter.Unsigned(raw), hex, value.Quality.ToString().ToLowerInvariant(), value.Error, shown, target.Symbol);
    }

    /// <summary>The value as the text shows it: in the format asked for, else unsigned; "-" when not read.</summary>
    public string ValueText() => Shown ?? Value?.ToString(System.Globalization.CultureInfo.InvariantCulture) ?? "-";

    /// <param name="o">Where the line goes.</param>
    /// <param name="valueWidth">
    /// The value column's width: the widest value of the read (a double word in binary takes 41), so hex and quality
    /// stay in their columns.
    /// </param>
    public void WriteText(TextWriter o, int valueWidth)
    {
        // The symbol is the project's (no control characters once loaded) and the error ours; shown so whatever they hold.
        var error = Error is null ? string.Empty : "  " + QuotedText.OneLine(Error);
        var symbol = Symbol is null ? string.Empty : "  " + QuotedText.OneLine(Symbol);
        o.WriteLine($"{Address,-8} {ValueText().PadRight(valueWidth)} {Hex ?? string.Empty,-12} {Quality}{symbol}{error}");
    }
}
