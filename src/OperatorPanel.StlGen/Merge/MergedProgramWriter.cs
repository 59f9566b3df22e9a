using OperatorPanel.Stl;
using OperatorPanel.StlGen.Emit;

namespace OperatorPanel.StlGen.Merge;

/// <summary>
/// Splices the generated handler into the user's program text: the user's lines are copied as they are (only the line
/// ends become CRLF; code-page characters stay, see <see cref="LineWriter.Copied"/>), but for the number of each
/// <c>Network n</c> line: every block counts its networks 1, 2, 3 ... as Micro/WIN exports them, the handler's network
/// being network 1 of OB1 and the user's following it. The handler's network goes first in OB1, its SBR and INTs go
/// among the user's blocks in number order. The handler's lines are taken from its own generated .awl, so the merged
/// file carries exactly what <see cref="HandlerGenerator"/> writes.
/// </summary>
internal static class MergedProgramWriter
{
    /// <summary>The file's lines without their line ends; a final line end does not make an extra empty line.</summary>
    public static IReadOnlyList<string> SplitLines(string text)
    {
        var lines = text.Split('\n').Select(l => l.TrimEnd('\r')).ToList();
        if (lines.Count > 1 && lines[^1].Length == 0)
        {
            lines.RemoveAt(lines.Count - 1);
        }

        return lines;
    }

    public static string Write(IReadOnlyList<string> userLines, AwlProgram user, string handlerText)
    {
        var handlerLines = SplitLines(handlerText);
        var handler = AwlParser.Parse(handlerText).Program;
        var main = handler.MainBlock!;
        var userMain = user.MainBlock!;
        var insertions = new List<(int BeforeLine, IEnumerable<string> Lines)>
        {
            (userMain.Networks.IsEmpty ? userMain.EndLine : userMain.Networks[0].Line, Slice(handlerLines, main.Networks[0].Line, main.EndLine - 1)),
        };
        foreach (var block in handler.Blocks.Where(b => b.Kind != AwlBlockKind.OrganizationBlock))
        {
            insertions.Add((InsertionLine(user, block, userLines.Count), Slice(handlerLines, block.StartLine, block.EndLine)));
        }

        var numbers = NetworkNumbers(user);
        var w = new LineWriter();
        for (var line = 1; line <= userLines.Count + 1; line++)
        {
            foreach (var (_, lines) in insertions.Where(i => i.BeforeLine == line))
            {
                foreach (var added in lines)
                {
                    w.Line(added);
                }
            }

            if (line <= userLines.Count)
            {
                w.Copied(numbers.TryGetValue(line, out var number) ? Renumbered(userLines[line - 1], number) : userLines[line - 1]);
            }
        }

        return w.ToString();
    }

    /// <summary>
    /// Before the first user block of the same kind with a higher number; else after the last block of that kind; else
    /// (no user block of the kind) after OB1 and the subroutines.
    /// </summary>
    private static int InsertionLine(AwlProgram user, AwlBlock block, int lineCount)
    {
        var sameKind = user.Blocks.Where(b => b.Kind == block.Kind).ToList();
        if (sameKind.FirstOrDefault(b => b.Number > block.Number) is { } next)
        {
            return next.StartLine;
        }

        var before = sameKind.Count > 0 ? sameKind : [.. user.Blocks.Where(b => b.Kind < block.Kind)];
        return before.Count == 0 ? lineCount + 1 : before.Max(b => b.EndLine) + 1;
    }

    /// <summary>The new number of each user <c>Network</c> line: 1, 2, 3 ... per block, from 2 in OB1 (the handler's network is 1).</summary>
    private static Dictionary<int, int> NetworkNumbers(AwlProgram user)
    {
        var numbers = new Dictionary<int, int>();
        foreach (var block in user.Blocks)
        {
            var next = block.Kind == AwlBlockKind.OrganizationBlock ? 2 : 1;
            foreach (var network in block.Networks)
            {
                numbers[network.Line] = next++;
            }
        }

        return numbers;
    }

    /// <summary>The line with the digits after its <c>Network</c> keyword replaced; a line that is not a Network line stays as it is.</summary>
    private static string Renumbered(string line, int number)
    {
        var keyword = line.TrimStart();
        var start = line.Length - keyword.Length;
        if (!keyword.StartsWith("NETWORK", StringComparison.OrdinalIgnoreCase))
        {
            return line;
        }

        var digits = start + "NETWORK".Length;
        while (digits < line.Length && line[digits] is ' ' or '\t')
        {
            digits++;
        }

        var end = digits;
        while (end < line.Length && char.IsAsciiDigit(line[end]))
        {
            end++;
        }

        return end == digits ? line : string.Concat(line.AsSpan(0, digits), number.ToString(System.Globalization.CultureInfo.InvariantCulture), line.AsSpan(end));
    }

    private static IEnumerable<string> Slice(IReadOnlyList<string> lines, int firstLine, int lastLine) =>
        lines.Skip(firstLine - 1).Take(lastLine - firstLine + 1);
}
