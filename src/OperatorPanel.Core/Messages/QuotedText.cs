using System.Globalization;
using System.Text;
using System.Text.RegularExpressions;

namespace OperatorPanel.Core.Messages;

/// <summary>
/// Keeps messages that quote user text readable (seen in the fuzz tests: .awl lines, addresses and values):
/// a control character shows as its code ("VB&lt;16#00&gt;1"; a NUL printed as is is invisible and "VB1" looks right),
/// and a run of more than <see cref="MaxWordChars"/> characters without a space keeps its first
/// <see cref="MaxWordChars"/> and "..." (a pasted megabyte would otherwise become a megabyte of message).
/// </summary>
public static partial class QuotedText
{
    public const int MaxWordChars = 40;

    /// <summary>A quote and a colon or comma end a quoted word; a longer run of them is text like any other.</summary>
    private const int MaxClosingChars = 2;

    public static string Readable(string message)
    {
        if (message.Any(IsHidden))
        {
            var shown = new StringBuilder(message.Length + 16);
            foreach (var c in message)
            {
                Append(shown, c, IsHidden(c));
            }

            message = shown.ToString();
        }

        return LongWord().Replace(message, m => Cut(m.Value));
    }

    /// <summary>
    /// <paramref name="text"/> with every control character shown as its code (<c>&lt;16#1B&gt;</c>), tab and line feed
    /// included: a name printed on one line of a terminal can then neither move the cursor, change colours (ESC [ 31 m)
    /// nor break the line. Nothing is cut; text without control characters comes back as it is.
    /// </summary>
    public static string OneLine(string text)
    {
        ArgumentNullException.ThrowIfNull(text);
        if (!text.Any(char.IsControl))
        {
            return text;
        }

        var shown = new StringBuilder(text.Length + 16);
        foreach (var c in text)
        {
            Append(shown, c, char.IsControl(c));
        }

        return shown.ToString();
    }

    /// <summary>
    /// The word's first <see cref="MaxWordChars"/> characters and "...", then the quote and colon that close it: the word
    /// runs on into them ("'VB999...9':"), and without them the message no longer reads as quote, then reason.
    /// </summary>
    private static string Cut(string word)
    {
        var end = word.Length;
        while (end > MaxWordChars && word.Length - end < MaxClosingChars && word[end - 1] is '\'' or '"' or ':' or ',' or ';' or ')')
        {
            end--;
        }

        return end <= MaxWordChars ? word : word[..MaxWordChars] + "..." + word[end..];
    }

    private static void Append(StringBuilder shown, char c, bool asCode)
    {
        if (asCode)
        {
            shown.Append(CultureInfo.InvariantCulture, $"<16#{(int)c:X2}>");
        }
        else
        {
            shown.Append(c);
        }
    }

    /// <summary>Tab and line feed lay a message out; every other control character is data the reader cannot see.</summary>
    private static bool IsHidden(char c) => char.IsControl(c) && c is not ('\t' or '\n');

    [GeneratedRegex(@"\S{41,}")]
    private static partial Regex LongWord();
}
