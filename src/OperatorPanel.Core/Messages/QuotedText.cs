using System.Text.RegularExpressions;

namespace OperatorPanel.Core.Messages;

/// <summary>
/// Keeps messages that quote user text readable: a run of more than <see cref="MaxWordChars"/> characters without a
/// space keeps its first <see cref="MaxWordChars"/> and "...". A pasted megabyte of digits or garbage otherwise becomes
/// a megabyte of error message (seen in the fuzz tests: .awl lines, addresses and values).
/// </summary>
internal static partial class QuotedText
{
    public const int MaxWordChars = 40;

    public static string CutLongWords(string message) =>
        LongWord().Replace(message, m => m.Value[..MaxWordChars] + "...");

    [GeneratedRegex(@"\S{41,}")]
    private static partial Regex LongWord();
}
