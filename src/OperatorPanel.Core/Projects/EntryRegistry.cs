using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Core.Projects;

/// <summary>
/// Remembers where each symbol and address of one station was first used, so a repeat is reported at the repeat
/// and names the first use. Symbols are compared ignoring case: an operator reads "Start" and "START" as one name.
/// </summary>
internal sealed class EntryRegistry
{
    private readonly Dictionary<string, string> _symbols = new(StringComparer.OrdinalIgnoreCase);
    private readonly Dictionary<(string List, PlcAddress Address), string> _addresses = [];

    /// <summary>Reads the entry's "symbol"; null when missing, blank or already used.</summary>
    public string? ClaimSymbol(JsonFields entry)
    {
        var symbol = TextRule.Symbol.Read(entry, "symbol");
        if (symbol is null)
        {
            return null;
        }

        if (string.IsNullOrWhiteSpace(symbol))
        {
            entry.Problem("symbol", "the symbol is empty");
            return null;
        }

        if (!_symbols.TryAdd(symbol.Trim(), entry.Path))
        {
            entry.Problem("symbol", $"symbol '{JsonPath.Shorten(symbol)}' is already used by {_symbols[symbol.Trim()]}");
            return null;
        }

        return symbol;
    }

    /// <summary>False, with a problem, when <paramref name="list"/> already holds <paramref name="address"/>.</summary>
    public bool ClaimAddress(JsonFields entry, string property, string list, PlcAddress address)
    {
        if (_addresses.TryAdd((list, address), entry.Path))
        {
            return true;
        }

        entry.Problem(property, $"{address} is already listed by {_addresses[(list, address)]}");
        return false;
    }
}
