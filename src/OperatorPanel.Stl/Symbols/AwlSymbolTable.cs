using System.Collections.Frozen;
using System.Collections.Immutable;
using System.Diagnostics.CodeAnalysis;

namespace OperatorPanel.Stl.Symbols;

/// <summary>
/// A symbol table exported from Micro/WIN (copied from its grid or exported as text): tab-separated, or the same table
/// saved as CSV (Core SymbolTableColumns), one symbol per line,
/// the symbol in the last non-empty column before the address and the comment after it; a header line and Micro/WIN's
/// icon columns are tolerated. The same format the project wizard's symbol import reads (Core SymbolTableImport), here
/// for every address an STL operand can name (V10.0, VW100, SMB30, T37, C5, AIW0, ...), not only I and Q bits.
/// </summary>
public sealed class AwlSymbolTable
{
    private readonly FrozenDictionary<string, string> _addresses;

    private AwlSymbolTable(Dictionary<string, string> addresses, ImmutableArray<AwlDiagnostic> rejected)
    {
        _addresses = addresses.ToFrozenDictionary(StringComparer.OrdinalIgnoreCase);
        Rejected = rejected;
    }

    /// <summary>Lines that hold something but no symbol and address, with their number and the reason.</summary>
    public ImmutableArray<AwlDiagnostic> Rejected { get; }

    public int Count => _addresses.Count;

    /// <summary>The address text a symbol stands for, whatever its case (no source found says whether Micro/WIN tells case apart in symbols).</summary>
    public bool TryGetAddress(string symbol, [NotNullWhen(true)] out string? address) => _addresses.TryGetValue(symbol, out address);

    public static AwlSymbolTable Parse(string text)
    {
        ArgumentNullException.ThrowIfNull(text);
        var addresses = new Dictionary<string, string>(StringComparer.OrdinalIgnoreCase);
        var rejected = ImmutableArray.CreateBuilder<AwlDiagnostic>();
        var lines = text.ReplaceLineEndings("\n").Split('\n');
        var contentSeen = false;
        for (var i = 0; i < lines.Length; i++)
        {
            var columns = Core.Projects.SymbolTableColumns.Split(lines[i]);
            if (columns.All(c => c.Length == 0))
            {
                continue;
            }

            var first = !contentSeen;
            contentSeen = true;
            var at = Array.FindIndex(columns, IsAddress);
            var symbol = at < 0 ? null : columns.Take(at).LastOrDefault(c => c.Length > 0);
            if (at < 0 || symbol is null)
            {
                // A first line without an address is the header ("Symbol  Address  Comment").
                if (!(first && at < 0))
                {
                    rejected.Add(new AwlDiagnostic(i + 1, at < 0 ? "no address on the line; a line holds a symbol, an address such as VW100 and a comment, separated by tabs (or by semicolons or commas)" : $"{columns[at]} has no symbol before it"));
                }

                continue;
            }

            if (addresses.TryGetValue(symbol, out var earlier) && earlier != columns[at])
            {
                rejected.Add(new AwlDiagnostic(i + 1, $"{symbol} is given twice, as {earlier} and {columns[at]}; the first is kept"));
                continue;
            }

            addresses.TryAdd(symbol, columns[at].ToUpperInvariant());
        }

        return new AwlSymbolTable(addresses, rejected.ToImmutable());
    }

    private static bool IsAddress(string cell) =>
        cell.Length > 0 && AwlOperand.TryParse(cell, out var operand, out _) && operand.Kind == AwlOperandKind.Address;
}
