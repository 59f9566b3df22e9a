using OperatorPanel.StlGen.Handler;

namespace OperatorPanel.StlGen.Emit;

/// <summary>
/// The handler's V bytes as Micro/WIN symbol table rows, Symbol TAB Address TAB Comment, to paste into an empty part of
/// the symbol table (the blocks' names are not symbols: Micro/WIN names POUs itself).
/// </summary>
public static class SymbolTableWriter
{
    public static string Write(HandlerLayout layout)
    {
        ArgumentNullException.ThrowIfNull(layout);
        var w = new LineWriter();
        foreach (var (symbol, address, comment) in layout.Symbols)
        {
            w.Line($"{symbol}\t{address}\t{comment}");
        }

        return w.ToString();
    }
}
