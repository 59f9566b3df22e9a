using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Core.Projects;

/// <summary>
/// Input and output symbols read from a Micro/WIN symbol table pasted as text (copied from the grid or exported):
/// tab-separated (or the same table saved as CSV: <see cref="SymbolTableColumns"/>), one symbol per line, the symbol in the last non-empty column before the address and the comment in the
/// first non-empty column after it. Extra columns (Micro/WIN's icon columns) and a header line are tolerated. Only I and
/// Q bits are kept; every other line with content is rejected with its number and the reason. The CPU's ranges are the
/// caller's to check, as for rows typed by hand.
/// </summary>
public sealed record SymbolTableImport(
    ImmutableArray<IoSymbol> Inputs, ImmutableArray<IoSymbol> Outputs, ImmutableArray<SymbolTableRejection> Rejected)
{
    public static SymbolTableImport Parse(string text)
    {
        ArgumentNullException.ThrowIfNull(text);
        var inputs = ImmutableArray.CreateBuilder<IoSymbol>();
        var outputs = ImmutableArray.CreateBuilder<IoSymbol>();
        var rejected = ImmutableArray.CreateBuilder<SymbolTableRejection>();
        var seen = new Dictionary<string, int>(StringComparer.OrdinalIgnoreCase);
        var lines = text.ReplaceLineEndings("\n").Split('\n');
        var contentSeen = false;
        for (var i = 0; i < lines.Length; i++)
        {
            var columns = SymbolTableColumns.Split(lines[i]);
            if (columns.All(c => c.Length == 0))
            {
                continue;
            }

            var isFirst = !contentSeen;
            contentSeen = true;
            var reason = Read(columns, out var symbol);
            if (reason is null && symbol is not null)
            {
                reason = Repeat(seen, symbol.Symbol, i + 1) ?? Repeat(seen, symbol.Address.ToString(), i + 1);
            }

            if (reason is not null)
            {
                // A first line without any address is the header ("Symbol  Address  Comment"), not a mistake.
                if (!(isFirst && reason == NoAddress))
                {
                    rejected.Add(new SymbolTableRejection(i + 1, lines[i], reason));
                }

                continue;
            }

            (symbol!.Address.Area == MemoryArea.I ? inputs : outputs).Add(symbol);
        }

        return new SymbolTableImport(inputs.ToImmutable(), outputs.ToImmutable(), rejected.ToImmutable());
    }

    private const string NoAddress = "no address found; a line holds a symbol, an address such as I0.0 and a comment, separated by tabs (or by semicolons or commas)";

    private static string? Read(string[] columns, out IoSymbol? symbol)
    {
        symbol = null;
        var at = Array.FindIndex(columns, c => PlcAddress.TryParse(c, out _, out _));
        if (at < 0)
        {
            return NoAddress;
        }

        var address = PlcAddress.Parse(columns[at]);
        if (address.Width != AccessWidth.Bit || address.Area is not (MemoryArea.I or MemoryArea.Q))
        {
            return $"{address} is not an input or output bit; only I and Q bits such as I0.0 or Q1.7 are imported here";
        }

        var name = columns.Take(at).LastOrDefault(c => c.Length > 0);
        if (name is null)
        {
            return $"{address} has no symbol before it";
        }

        symbol = new IoSymbol(name, address, columns.Skip(at + 1).FirstOrDefault(c => c.Length > 0) ?? string.Empty);
        return null;
    }

    private static string? Repeat(Dictionary<string, int> seen, string key, int lineNumber) =>
        seen.TryAdd(key, lineNumber) ? null : $"{key} is already on line {seen[key]}";
}
