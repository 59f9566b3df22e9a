using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;

namespace OperatorPanel.Core.Projects;

/// <summary>
/// Reads a station's <c>tags</c>: memory cells of M and V (seed 000 §7), or read-only views of I, Q and SM.
/// Two tags may share an address, e.g. VD120 shown once as a float and once in hex.
/// </summary>
internal static class TagReader
{
    public static ImmutableArray<ProjectTag>? ReadAll(JsonFields station, CpuProfile? cpu, EntryRegistry registry) =>
        station.Entries("tags", entry => Read(entry, cpu, registry));

    private static ProjectTag? Read(JsonFields entry, CpuProfile? cpu, EntryRegistry registry)
    {
        entry.ReportUnknown("symbol", "address", "format", "writable", "description", "record", "deadband");
        var symbol = registry.ClaimSymbol(entry);
        var writable = entry.Bool("writable", fallback: false);
        var use = writable == true ? AddressUse.Write : AddressUse.Read;
        var address = AddressReader.Read(entry, "address", cpu, Shape, use);
        var format = entry.Word("format", DisplayFormats.DefaultFor(address?.Width ?? AccessWidth.Bit));
        if (address is { } a && format is { } f && !f.Fits(a.Width))
        {
            entry.Problem("format", $"{JsonWords.Of(f)} cannot show {a}, {AddressReader.Kind(a)}; {FitHint(f)}");
            format = null;
        }

        var description = entry.String("description", string.Empty);
        var recorded = entry.Bool("record", fallback: true);
        var deadbandOk = entry.TryNullableNumber("deadband", out var deadband);
        if (deadband is < 0)
        {
            entry.Problem("deadband", "a deadband cannot be negative; 0 records every change");
            deadbandOk = false;
        }

        return symbol is null || address is null || format is null || writable is null || description is null || recorded is null || !deadbandOk
            ? null
            : new ProjectTag(symbol, address.Value, format.Value, writable.Value, description) { Recorded = recorded.Value, Deadband = deadband };
    }

    private static string? Shape(PlcAddress address) => AddressRules.IsServedByLink(address.Area)
        ? null
        : $"{address}: the panel link serves only I, Q, M, V and SM";

    private static string FitHint(DisplayFormat format) => format switch
    {
        DisplayFormat.Bool => "bool is for bits",
        DisplayFormat.Float => "float is for double words (VD, MD)",
        DisplayFormat.Unsigned or DisplayFormat.Signed or DisplayFormat.Hex or DisplayFormat.Binary or DisplayFormat.Ascii =>
            $"{JsonWords.Of(format)} is for bytes, words and double words; use bool for a bit",
    };
}
