using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Values;

namespace OperatorPanel.Cli.Commands;

/// <summary>One address as <c>opanel read</c> prints it (text and JSON share this shape).</summary>
internal sealed record ReadValueView(string Address, ulong? Value, string? Hex, string Quality, string? Error)
{
    public static ReadValueView From(PlcAddress address, PolledValue? value)
    {
        if (value is not { HasValue: true })
        {
            return new ReadValueView(address.ToString(), null, null, "bad", value?.Error ?? "not read");
        }

        var raw = value.Raw.AsSpan();
        var hex = address.Width == AccessWidth.Bit ? null : ValueFormatter.Hex(raw);
        return new ReadValueView(address.ToString(), ValueFormatter.Unsigned(raw), hex, value.Quality.ToString().ToLowerInvariant(), value.Error);
    }

    public void WriteText(TextWriter o)
    {
        var value = Value?.ToString(System.Globalization.CultureInfo.InvariantCulture) ?? "-";
        var error = Error is null ? string.Empty : "  " + Error;
        o.WriteLine($"{Address,-8} {value,-11} {Hex ?? string.Empty,-12} {Quality}{error}");
    }
}
