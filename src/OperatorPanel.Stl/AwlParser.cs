using System.Collections.Immutable;

namespace OperatorPanel.Stl;

/// <summary>
/// Reads the .awl text Micro/WIN exports (File > Export) and imports: blocks, headers, variable tables, networks and
/// instruction lines (docs: /work/briefs/stl-dialect.md, "File format"). Tolerates blank lines, <c>//</c> comments
/// anywhere, CRLF or LF. Never throws on bad text: every line it cannot place becomes a diagnostic.
/// </summary>
public static class AwlParser
{
    /// <summary>The UTF-8 byte order mark as read one character per byte (Latin-1), and as read as UTF-8.</summary>
    private static readonly string[] ByteOrderMarks = ["\u00EF\u00BB\u00BF", "\uFEFF"];

    public static AwlParseResult Parse(string text)
    {
        ArgumentNullException.ThrowIfNull(text);
        var reader = new AwlReader();
        var lines = text.Split('\n');
        if (ByteOrderMarks.FirstOrDefault(mark => lines[0].StartsWith(mark, StringComparison.Ordinal)) is { } mark)
        {
            // Notepad's "UTF-8" adds one; the rest of the file is still read, so its other problems are reported too.
            reader.Diagnostics.Add(new AwlDiagnostic(1, "the file starts with a UTF-8 byte order mark (EF BB BF); Micro/WIN exports in the Windows code page without one: save the file as ANSI"));
            lines[0] = lines[0][mark.Length..];
        }

        for (var i = 0; i < lines.Length; i++)
        {
            var line = lines[i].TrimEnd('\r');
            if (line.Contains('\r', StringComparison.Ordinal))
            {
                // A lone CR (an old Mac line end, a bad copy) ends the line for some editors and not for others;
                // reported rather than guessed, and read as a space so the rest of the file is still checked.
                reader.Diagnostics.Add(new AwlDiagnostic(i + 1, "a carriage return (16#0D) inside the line; a line ends with CR LF or LF, and text after a lone CR would be misread"));
                line = line.Replace('\r', ' ');
            }

            reader.Read(line, i + 1);
        }

        reader.Finish(lines.Length);
        return new AwlParseResult(new AwlProgram(reader.Blocks.ToImmutable()), reader.Diagnostics.ToImmutable());
    }

    /// <summary>Splits "text // comment" at the first <c>//</c> outside a quoted string.</summary>
    internal static (string Code, string Comment) SplitComment(string line)
    {
        var quote = '\0';
        for (var i = 0; i < line.Length; i++)
        {
            var c = line[i];
            if (quote != '\0')
            {
                quote = c == quote ? '\0' : quote;
            }
            else if (c is '\'' or '"')
            {
                quote = c;
            }
            else if (c == '/' && i + 1 < line.Length && line[i + 1] == '/')
            {
                return (line[..i].Trim(), line[(i + 2)..].Trim());
            }
        }

        return (line.Trim(), string.Empty);
    }

    /// <summary>Splits an operand list at commas outside quoted strings.</summary>
    internal static ImmutableArray<string> SplitOperands(string text)
    {
        var operands = ImmutableArray.CreateBuilder<string>();
        if (text.Trim().Length == 0)
        {
            return operands.ToImmutable();
        }

        var quote = '\0';
        var start = 0;
        for (var i = 0; i < text.Length; i++)
        {
            var c = text[i];
            if (quote != '\0')
            {
                quote = c == quote ? '\0' : quote;
            }
            else if (c is '\'' or '"')
            {
                quote = c;
            }
            else if (c == ',')
            {
                operands.Add(text[start..i].Trim());
                start = i + 1;
            }
        }

        operands.Add(text[start..].Trim());
        return operands.ToImmutable();
    }
}
