using OperatorPanel.Stl.Instructions;

namespace OperatorPanel.Stl.Tests.Instructions;

/// <summary>
/// docs/stl-instructions.md and <see cref="StlInstructionTable"/> say the same: one row per entry, in table order,
/// every cell equal. OPANEL_BLESS=1 rewrites the rows between the markers from the code; review the diff (and the
/// sources) before committing.
/// </summary>
public sealed class StlInstructionDocTests
{
    private const string Begin = "<!-- instruction table: begin -->";
    private const string End = "<!-- instruction table: end -->";

    [Fact]
    public void Doc_ListsEveryEntryOfTheCodeTable_CellByCell()
    {
        var path = Path.Combine(RepositoryRoot(), "docs", "stl-instructions.md");
        var text = File.ReadAllText(path);
        var expected = StlInstructionTable.All.Select(StlInstructionDocRow.Format).ToList();
        if (Environment.GetEnvironmentVariable("OPANEL_BLESS") == "1")
        {
            File.WriteAllText(path, Rewrite(text, expected));
            text = File.ReadAllText(path);
        }

        var rows = Rows(text);

        rows.Select(r => r.Split(" | ")[0]).Should().Equal(expected.Select(r => r.Split(" | ")[0]), "the doc lists the mnemonics in the code table's order");
        rows.Should().Equal(expected);
    }

    [Fact]
    public void Doc_CountsTheEntriesItLists()
    {
        var text = File.ReadAllText(Path.Combine(RepositoryRoot(), "docs", "stl-instructions.md"));

        text.Should().Contain($"{StlInstructionTable.All.Length} entries");
    }

    private static List<string> Rows(string text)
    {
        var start = text.IndexOf(Begin, StringComparison.Ordinal);
        var end = text.IndexOf(End, StringComparison.Ordinal);
        start.Should().BeGreaterThan(0, "the doc marks its instruction table");
        return [.. text[start..end].Split('\n').Select(l => l.TrimEnd('\r')).Where(l => l.StartsWith("| `", StringComparison.Ordinal))];
    }

    private static string Rewrite(string text, List<string> rows)
    {
        var start = text.IndexOf(Begin, StringComparison.Ordinal) + Begin.Length;
        var end = text.IndexOf(End, StringComparison.Ordinal);
        var table = "\n" + StlInstructionDocRow.Header + "\n|---|---|---|---|---|---|---|\n" + string.Join("\n", rows) + "\n";
        return text[..start] + table + text[end..];
    }

    private static string RepositoryRoot()
    {
        var dir = new DirectoryInfo(AppContext.BaseDirectory);
        while (dir is not null && !File.Exists(Path.Combine(dir.FullName, "OperatorPanel.sln")))
        {
            dir = dir.Parent;
        }

        return dir?.FullName ?? throw new InvalidOperationException("OperatorPanel.sln not found above " + AppContext.BaseDirectory);
    }
}
