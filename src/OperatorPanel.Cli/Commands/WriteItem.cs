using System.Diagnostics.CodeAnalysis;
using OperatorPanel.Cli.Link;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Values;
using OperatorPanel.Core.Writes;

namespace OperatorPanel.Cli.Commands;

/// <summary>
/// One <c>ADDR=VALUE</c> or, with --project, <c>SYMBOL=VALUE</c> of <c>opanel write</c>, checked: the address, the value
/// in the notation it is typed in (a symbol's value in its tag's units: RecipeNumber=3, TankLevel=55.2), the tag's
/// range and the read-only tags whichever way the cell is named, the handler's own V bytes, the request. <see cref="Tag"/> is set when values show in the tag's format.
/// </summary>
internal sealed record WriteItem(PlcAddress Address, DisplayFormat Format, WriteRequest Request, ProjectTag? Tag = null)
{
    public static bool TryParse(string text, LinkTarget target, [NotNullWhen(true)] out WriteItem? item, [NotNullWhen(false)] out string? error) =>
        TryParse(text, target, null, out item, out error);

    public static bool TryParse(string text, LinkTarget target, ProjectStation? station, [NotNullWhen(true)] out WriteItem? item, [NotNullWhen(false)] out string? error)
    {
        item = null;
        var equals = text.IndexOf('=', StringComparison.Ordinal);
        if (equals < 0)
        {
            error = $"'{text}': write ADDR=VALUE, e.g. VW200=1234{(station is null ? string.Empty : " or SYMBOL=VALUE")}";
            return false;
        }

        if (!ArgumentTarget.TryResolve(text[..equals], target, station, AddressUse.Write, out var named, out error))
        {
            return false;
        }

        var address = named.Address;
        if (named is { BySymbol: true, Tag.Writable: false })
        {
            error = $"{address}: the project marks {named.Tag.Symbol} read-only";
            return false;
        }

        // However the cell is named, the project's read-only tags and the handler's own V bytes are refused here, before
        // anything is read or sent (Core's WriteRules, as the Memory window's): the PLC would refuse the handler's with 83.
        if (WriteRules.Refusal(address, target.Serial.Protocol, target.Cpu, station) is { } refused)
        {
            error = refused;
            return false;
        }

        var valueText = text[(equals + 1)..];
        var shownAs = named is { BySymbol: true, Tag: { } tag } ? tag : null;
        var format = shownAs?.Format ?? ValueFormatInference.Infer(valueText, address.Width);
        ValueError? valueError;
        var parsed = shownAs is not null
            ? TagValues.TryParse(shownAs, valueText, out var bytes, out valueError)
            : ValueParser.TryParse(valueText, address, format, out bytes, out valueError);
        if (!parsed)
        {
            error = valueError!.Message;
            return false;
        }

        if (shownAs is null && OutsideRange(named.Tag, bytes.AsSpan()) is { } outside)
        {
            error = $"{text}: {outside}";
            return false;
        }

        var request = address.Width == AccessWidth.Bit
            ? WriteRequest.Bit(target.Station, address, bytes[0] != 0)
            : WriteRequest.Bytes(target.Station, address, bytes);
        item = new WriteItem(address, format, request with { Symbol = named.Symbol }, shownAs);
        return true;
    }

    /// <summary>Bytes in this item's format (a symbol's: its tag's, scaled, with unit); "?" when unknown.</summary>
    public string Show(ReadOnlySpan<byte> raw) =>
        raw.IsEmpty ? "?" : Tag is { } tag ? TagValues.Format(tag, raw) : ValueFormatter.Format(raw, Address.Width, Format);

    /// <summary>A cell named by its address still keeps its tag's range: the raw value, scaled, must lie inside it.</summary>
    private static string? OutsideRange(ProjectTag? tag, ReadOnlySpan<byte> raw)
    {
        if (tag is not { Range: { } range } || !TagValues.IsNumeric(tag.Format))
        {
            return null;
        }

        var value = TagValues.RawNumber(tag.Format, raw);
        value = tag.Scale?.ToValue(value) ?? value;
        var unit = tag.Unit is { } u ? " " + u : string.Empty;
        return range.Contains(value) ? null : $"{tag.Symbol} ({tag.Address}) is {TagScale.Number(value)}{unit} with that, outside its range {range}{unit}";
    }
}
