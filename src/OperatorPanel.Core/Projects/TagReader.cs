using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Transport;
using OperatorPanel.Core.Values;

namespace OperatorPanel.Core.Projects;

/// <summary>
/// Reads a station's <c>tags</c>: memory cells of M and V (seed 000 §7), or views of I, Q and SM; on a PPI station also
/// of S, AIW, AQW and timer and counter current values (T37, C5), which the Freeport link does not reach (<see cref="LinkAreas"/>).
/// Two tags may share an address, e.g. VD120 shown once as a float and once in hex. Optional, as an HMI has them:
/// <c>unit</c>, <c>scale</c> (<c>{"rawLow", "rawHigh", "low", "high"}</c>, linear) and <c>min</c>/<c>max</c> (what the
/// operator may write, in scaled units); scale and range only for numbers (unsigned, signed, float).
/// </summary>
internal static class TagReader
{
    public static ImmutableArray<ProjectTag>? ReadAll(JsonFields station, CpuProfile? cpu, LinkProtocol? link, EntryRegistry registry) =>
        station.Entries("tags", entry => Read(entry, cpu, link, registry));

    private static ProjectTag? Read(JsonFields entry, CpuProfile? cpu, LinkProtocol? link, EntryRegistry registry)
    {
        entry.ReportUnknown("symbol", "address", "format", "writable", "description", "unit", "scale", "min", "max", "record", "deadband");
        var symbol = registry.ClaimSymbol(entry);
        var writable = entry.Bool("writable", fallback: false);
        var use = writable == true ? AddressUse.Write : AddressUse.Read;
        var address = AddressReader.Read(entry, "address", cpu, _ => null, use, link);
        var format = entry.Word("format", address is { } read ? DisplayFormats.DefaultFor(read) : DisplayFormat.Bool);
        if (address is { } a && format is { } f && !f.Fits(a.Width))
        {
            entry.Problem("format", $"{JsonWords.Of(f)} cannot show {a}, {AddressReader.Kind(a)}; {FitHint(f)}");
            format = null;
        }

        var description = TextRule.Description.Read(entry, "description", string.Empty);
        var recorded = entry.Bool("record", fallback: true);
        var deadbandOk = entry.TryNullableNumber("deadband", out var deadband);
        if (deadband is < 0)
        {
            entry.Problem("deadband", "a deadband cannot be negative; 0 records every change");
            deadbandOk = false;
        }

        var tag = symbol is null || address is null || format is null || writable is null || description is null || recorded is null || !deadbandOk
            ? null
            : new ProjectTag(symbol, address.Value, format.Value, writable.Value, description) { Recorded = recorded.Value, Deadband = deadband };
        return ReadEngineering(entry, tag);
    }

    /// <summary>Unit, scale and range of <paramref name="tag"/> (null when its basics failed; their problems are reported).</summary>
    private static ProjectTag? ReadEngineering(JsonFields entry, ProjectTag? tag)
    {
        var ok = true;
        var unit = entry.Has("unit") ? entry.String("unit") : null;
        ok &= unit is not null || !entry.Has("unit");
        var scale = ReadScale(entry, ref ok);
        var min = entry.Has("min") ? entry.Number("min") : null;
        var max = entry.Has("max") ? entry.Number("max") : null;
        ok &= (min is not null || !entry.Has("min")) && (max is not null || !entry.Has("max"));
        if (!ok || tag is null)
        {
            return null;
        }

        tag = tag with { Unit = unit, Scale = scale, Range = min is null && max is null ? null : new TagRange(min, max) };
        if (TagRules.Problem(tag) is var (property, message))
        {
            entry.Problem(property, message);
            return null;
        }

        return tag;
    }

    private static TagScale? ReadScale(JsonFields entry, ref bool ok)
    {
        if (!entry.Has("scale"))
        {
            return null;
        }

        var fields = entry.Object("scale");
        fields?.ReportUnknown("rawLow", "rawHigh", "low", "high");
        var (rawLow, rawHigh, low, high) = (fields?.Number("rawLow"), fields?.Number("rawHigh"), fields?.Number("low"), fields?.Number("high"));
        if (rawLow is not { } rl || rawHigh is not { } rh || low is not { } l || high is not { } h)
        {
            ok = false;
            return null;
        }

        return new TagScale(rl, rh, l, h);
    }

    private static string FitHint(DisplayFormat format) => format switch
    {
        DisplayFormat.Bool => "bool is for bits",
        DisplayFormat.Float => "float is for double words (VD, MD)",
        DisplayFormat.Unsigned or DisplayFormat.Signed or DisplayFormat.Hex or DisplayFormat.Binary or DisplayFormat.Ascii =>
            $"{JsonWords.Of(format)} is for bytes, words and double words; use bool for a bit",
    };
}
