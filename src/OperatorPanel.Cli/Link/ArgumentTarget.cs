using System.Diagnostics.CodeAnalysis;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Projects;

namespace OperatorPanel.Cli.Link;

/// <summary>
/// What a read or write argument names: an address (VB110), or with --project a symbol of the station (RecipeNumber, a
/// tag, input or output, compared ignoring case). <see cref="Tag"/> is the station's memory cell at that address, whose
/// format, scale, unit and range then apply; null when the station has none there.
/// </summary>
internal sealed record ArgumentTarget(PlcAddress Address, ProjectTag? Tag, string? Symbol, bool BySymbol)
{
    public static bool TryResolve(
        string text, LinkTarget target, ProjectStation? station, AddressUse use, [NotNullWhen(true)] out ArgumentTarget? resolved, [NotNullWhen(false)] out string? error)
    {
        resolved = null;
        var trimmed = text.Trim();
        if (station is not null && Find(station, trimmed) is { } found)
        {
            var tag = station.Tags.FirstOrDefault(t => string.Equals(t.Symbol, trimmed, StringComparison.OrdinalIgnoreCase));
            return Check(found, target, use, out error) && Set(new ArgumentTarget(found, tag, station.SymbolOf(found), BySymbol: true), out resolved);
        }

        if (!AddressArguments.TryParse(trimmed, target.Cpu, target.Serial.Protocol, use, out var address, out error))
        {
            // Only a word that is no area at all may have been meant as a symbol; T37 or AIW0 were meant as addresses.
            var unknown = !PlcAddress.TryParse(trimmed, out _, out var syntax) && syntax.Kind == AddressErrorKind.UnknownArea
                && syntax.Message.Contains("unknown memory area", StringComparison.Ordinal);
            error = (unknown, station) switch
            {
                (true, not null) => $"'{trimmed}': no tag, input or output of {station.Name} has this symbol, and it is no address ({error})",
                (true, null) => $"{error} (a tag's symbol works with --project)",
                _ => error,
            };
            return false;
        }

        var cell = station?.Tags.FirstOrDefault(t => t.Address == address);
        return Set(new ArgumentTarget(address, cell, station?.SymbolOf(address), BySymbol: false), out resolved);
    }

    private static PlcAddress? Find(ProjectStation station, string symbol) =>
        station.Tags.FirstOrDefault(t => Same(t.Symbol, symbol))?.Address
        ?? station.Outputs.FirstOrDefault(s => Same(s.Symbol, symbol))?.Address
        ?? station.Inputs.FirstOrDefault(s => Same(s.Symbol, symbol))?.Address;

    private static bool Same(string a, string b) => string.Equals(a, b, StringComparison.OrdinalIgnoreCase);

    /// <summary>A symbol's address goes through the same checks as a typed one (link, CPU, writable).</summary>
    private static bool Check(PlcAddress address, LinkTarget target, AddressUse use, [NotNullWhen(false)] out string? error) =>
        AddressArguments.TryParse(address.ToString(), target.Cpu, target.Serial.Protocol, use, out _, out error);

    private static bool Set(ArgumentTarget value, out ArgumentTarget resolved)
    {
        resolved = value;
        return true;
    }
}
