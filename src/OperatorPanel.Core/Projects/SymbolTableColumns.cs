namespace OperatorPanel.Core.Projects;

/// <summary>
/// The columns of one line of a symbol table as users bring it: Micro/WIN's grid copied or exported as text
/// (tab-separated), or the same table saved from a spreadsheet as CSV, which separates with a semicolon where the decimal
/// comma is used and a comma elsewhere (a public S7-200 project, Sebaasu/xk335b-scada, keeps its table as
/// <c>Symbol;Address;Comment</c>). A line with a tab is split on tabs only; otherwise on semicolons, else on commas,
/// outside double quotes. Each column is trimmed and unquoted ("a ""b""" is a "b"). The readers take the symbol from
/// the last non-empty column before the address, so a comment that a comma splits only adds columns after it.
/// </summary>
public static class SymbolTableColumns
{
    public static string[] Split(string line)
    {
        ArgumentNullException.ThrowIfNull(line);
        var separator = line.Contains('\t', StringComparison.Ordinal) ? '\t'
            : OutsideQuotes(line, ';') ? ';'
            : ',';
        var columns = new List<string>();
        var cell = new System.Text.StringBuilder();
        var quoted = false;
        for (var i = 0; i < line.Length; i++)
        {
            var c = line[i];
            if (c == '"' && separator != '\t')
            {
                if (quoted && i + 1 < line.Length && line[i + 1] == '"')
                {
                    cell.Append('"');
                    i++;
                }
                else
                {
                    quoted = !quoted;
                }
            }
            else if (c == separator && !quoted)
            {
                columns.Add(Cell(cell.ToString(), separator));
                cell.Clear();
            }
            else
            {
                cell.Append(c);
            }
        }

        columns.Add(Cell(cell.ToString(), separator));
        return [.. columns];
    }

    /// <summary>
    /// A CSV cell's quotes were taken out while splitting; Micro/WIN's tab text has none, but a tab-separated cell copied
    /// through a spreadsheet may be quoted whole.
    /// </summary>
    private static string Cell(string cell, char separator) => separator == '\t' ? Unquote(cell) : cell.Trim();

    private static string Unquote(string cell)
    {
        var trimmed = cell.Trim();
        return trimmed.Length >= 2 && trimmed[0] == '"' && trimmed[^1] == '"'
            ? trimmed[1..^1].Replace("\"\"", "\"", StringComparison.Ordinal).Trim()
            : trimmed;
    }

    private static bool OutsideQuotes(string line, char separator)
    {
        var quoted = false;
        foreach (var c in line)
        {
            if (c == '"')
            {
                quoted = !quoted;
            }
            else if (c == separator && !quoted)
            {
                return true;
            }
        }

        return false;
    }
}
