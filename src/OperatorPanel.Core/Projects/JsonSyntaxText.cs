using System.Text;
using System.Text.Json;
using OperatorPanel.Core.Messages;

namespace OperatorPanel.Core.Projects;

/// <summary>
/// A JSON syntax error of a project file said in our words, from the text around the place the reader stopped: a
/// trailing comma, a comment, single quotes, a missing comma or colon, a word without quotes, a file cut short. The
/// reader's own sentences ("...when isFinalBlock is true", "Change the reader options") speak to programmers, and are
/// never shown. Hand-edited project files are the audience: these are the mistakes people make in them.
/// </summary>
internal static class JsonSyntaxText
{
    private const string Empty = "there is no text; a project file is JSON text starting with '{'";

    public static string Describe(string text, JsonException ex)
    {
        ArgumentNullException.ThrowIfNull(text);
        ArgumentNullException.ThrowIfNull(ex);
        if (text.Trim().Length == 0)
        {
            return Empty;
        }

        var at = IndexOf(text, ex);
        if (text.AsSpan(Math.Min(at, text.Length)).Trim().IsEmpty)
        {
            return "the text ends too early: a closing '}' or ']' is missing (was the file cut short?)";
        }

        var context = Scan(text, at);
        var c = text[at];
        var before = context.Previous is { } p ? text[p] : '\0';
        return c switch
        {
            _ when context.InString && char.IsControl(c) => "a line break or control character inside text in quotes; write it as \\n or \\t",
            _ when context.InString => "a backslash in text in quotes must be followed by \", \\, /, b, f, n, r, t or u (write \\\\ for one backslash)",
            _ when context.InNumber => "a number is not written correctly; write it like 12, -3 or 1.5",
            '}' or ']' when before == ',' => $"a comma before '{c}' has nothing after it; remove that comma",
            '}' or ']' when before == ':' => "a value is missing after ':'",
            ',' when before is ',' or '{' or '[' or ':' => "a value is missing before this comma",
            '/' => "comments (// or /* */) are not allowed in a project file",
            '\'' => "names and text go in double quotes (\"), not single quotes",
            _ when context.Depth == 0 && context.Previous is not null => "there is more text after the end of the JSON",
            _ when char.IsLetter(c) && !StartsLiteral(text, at) => $"'{QuotedText.Readable(Word(text, at))}' is not a value: text goes in double quotes, and true, false and null in lower case",
            _ when context.AfterName => "a colon ':' is missing after the name",
            _ when EndsValue(before) => "a comma is missing before this",
            '}' or ']' => $"'{c}' does not close the bracket opened before it; the brackets do not pair up",
            _ => $"unexpected character '{QuotedText.Readable(c.ToString())}'",
        };
    }

    /// <summary>The character index where the reader stopped (it counts lines from 0 and bytes within the line).</summary>
    private static int IndexOf(string text, JsonException ex)
    {
        var line = (int)Math.Clamp(ex.LineNumber ?? 0, 0, int.MaxValue);
        var start = 0;
        for (var i = 0; i < line && start >= 0; i++)
        {
            start = text.IndexOf('\n', start) is var n and >= 0 ? n + 1 : -1;
        }

        if (start < 0)
        {
            return text.Length;
        }

        var end = text.IndexOf('\n', start) is var e and >= 0 ? e : text.Length;
        var bytes = Encoding.UTF8.GetBytes(text[start..end]);
        var column = (int)Math.Clamp(ex.BytePositionInLine ?? 0, 0, bytes.Length);
        return start + Encoding.UTF8.GetCharCount(bytes, 0, column);
    }

    /// <summary>Walks the text up to <paramref name="at"/>: open brackets, strings, the last significant character.</summary>
    private static Context Scan(string text, int at)
    {
        var depth = 0;
        var inString = false;
        var escaped = false;
        int? previous = null;
        int? stringStart = null;
        int? lastStringStart = null;
        for (var i = 0; i < at; i++)
        {
            var c = text[i];
            if (inString)
            {
                (escaped, inString) = escaped ? (false, true) : (c == '\\', c != '"');
                previous = i;
                lastStringStart = inString ? lastStringStart : stringStart;
                continue;
            }

            if (char.IsWhiteSpace(c))
            {
                continue;
            }

            (depth, inString, stringStart) = c switch
            {
                '{' or '[' => (depth + 1, false, stringStart),
                '}' or ']' => (depth - 1, false, stringStart),
                '"' => (depth, true, i),
                _ => (depth, false, stringStart),
            };
            previous = i;
        }

        var inNumber = previous == at - 1 && at > 0 && (char.IsAsciiDigit(text[at - 1]) || text[at - 1] is '-' or '.' or 'e' or 'E' or '+') && !inString
            && NumberStarts(text, at - 1);
        var afterName = previous is { } p && text[p] == '"' && lastStringStart is { } s && Before(text, s) is '{' or ',' && IsInObject(text, s);
        return new Context(depth, inString, inNumber, afterName, previous);
    }

    /// <summary>The run ending at <paramref name="last"/> is a number: it started with a digit or '-'.</summary>
    private static bool NumberStarts(string text, int last)
    {
        var i = last;
        while (i > 0 && (char.IsAsciiDigit(text[i - 1]) || text[i - 1] is '-' or '.' or 'e' or 'E' or '+'))
        {
            i--;
        }

        return char.IsAsciiDigit(text[i]) || text[i] == '-';
    }

    private static char Before(string text, int index)
    {
        for (var i = index - 1; i >= 0; i--)
        {
            if (!char.IsWhiteSpace(text[i]))
            {
                return text[i];
            }
        }

        return '\0';
    }

    /// <summary>True when the innermost bracket open at <paramref name="index"/> is '{' (strings skipped).</summary>
    private static bool IsInObject(string text, int index)
    {
        var open = new Stack<char>();
        var inString = false;
        var escaped = false;
        for (var i = 0; i < index; i++)
        {
            var c = text[i];
            if (inString)
            {
                (escaped, inString) = escaped ? (false, true) : (c == '\\', c != '"');
            }
            else if (c == '"')
            {
                inString = true;
            }
            else if (c is '{' or '[')
            {
                open.Push(c);
            }
            else if (c is '}' or ']' && open.Count > 0)
            {
                open.Pop();
            }
        }

        return open.TryPeek(out var top) && top == '{';
    }

    private static bool EndsValue(char c) => char.IsAsciiDigit(c) || c is '"' or '}' or ']' or 'e' or 'l';

    private static bool StartsLiteral(string text, int at) => Word(text, at) is "true" or "false" or "null";

    private static string Word(string text, int at)
    {
        var end = at;
        while (end < text.Length && end - at < QuotedText.MaxWordChars && (char.IsLetterOrDigit(text[end]) || text[end] == '_'))
        {
            end++;
        }

        return text[at..end];
    }

    private sealed record Context(int Depth, bool InString, bool InNumber, bool AfterName, int? Previous);
}
