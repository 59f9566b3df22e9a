using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;

namespace OperatorPanel.Core.Projects;

/// <summary>Reads a station's <c>inputs</c> (I bits) or <c>outputs</c> (Q bits): symbol, address, description.</summary>
internal static class IoSymbolReader
{
    public static ImmutableArray<IoSymbol>? ReadAll(JsonFields station, string list, MemoryArea area, CpuProfile? cpu, EntryRegistry registry)
    {
        var noun = area == MemoryArea.I ? "an input is an I bit such as I0.0" : "an output is a Q bit such as Q0.0";
        return station.Entries(list, entry =>
        {
            entry.ReportUnknown("symbol", "address", "description");
            var symbol = registry.ClaimSymbol(entry);
            var address = AddressReader.Read(entry, "address", cpu, a => a.Area == area && a.Width == AccessWidth.Bit ? null : $"{noun}, not {a}");
            var description = TextRule.Description.Read(entry, "description", string.Empty);
            if (address is { } a && !registry.ClaimAddress(entry, "address", list, a))
            {
                address = null;
            }

            return symbol is null || address is null || description is null ? null : new IoSymbol(symbol, address.Value, description);
        });
    }
}
