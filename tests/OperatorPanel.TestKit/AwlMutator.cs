namespace OperatorPanel.TestKit;

/// <summary>One random edit of .awl text, described so a failure can be reproduced by hand.</summary>
public static class AwlMutator
{
    /// <summary>Words of the dialect and operands that are wrong in every way a hand edit or a bad copy makes them.</summary>
    private static readonly string[] Tokens =
    [
        "LD", "A", "=", "MOVB", "MOVW", "MOVD", "CALL", "ATCH", "RCV", "XMT", "FOR", "NEXT", "JMP", "LBL", "LSCR", "SCRE",
        "TON", "CTU", "BEGIN", "END_SUBROUTINE_BLOCK", "END_ORGANIZATION_BLOCK", "SUBROUTINE_BLOCK", "INTERRUPT_BLOCK",
        "ORGANIZATION_BLOCK", "Network", "VAR_INPUT", "END_VAR", "VB99999999999999999999", "VW-1", "16#GG", "16#", "2#102",
        "99999999999999999999", "-2147483649", "4294967296", "1.0E400", "NaN", "*VD", "*AC9", "&VB", "&", "#", "#x", "LW64",
        "L", "T999", "C-1", "I9.9", "Q0.8", "SM0.", "V.1", "M", "AC4", "'", "\"", "''", "'abc", ",", ",,", "(", ")", "\0",
        "OP_PANEL", "SBR63", "INT_0", "SBR_99", "TITLE=", "//", "\t", "\u00FF", "\uFFFD",
    ];

    /// <summary>A seed fixed per source name (string.GetHashCode is randomised per process).</summary>
    public static int Seed(string source) => source.Aggregate(17, (hash, c) => unchecked((hash * 31) + c));

    public static (string Text, string How) Mutate(string text, Random random)
    {
        var lines = text.Split('\n').ToList();
        var at = random.Next(lines.Count);
        var token = Tokens[random.Next(Tokens.Length)];
        switch (random.Next(7))
        {
            case 0:
                lines.RemoveAt(at);
                return (string.Join('\n', lines), $"line {at + 1} cut");
            case 1:
                var length = random.Next(text.Length);
                return (text[..length], $"truncated to {length} characters");
            case 2:
                var words = lines[at].Split(' ', StringSplitOptions.RemoveEmptyEntries).ToList();
                words.Insert(random.Next(words.Count + 1), token);
                lines[at] = string.Join(' ', words);
                return (string.Join('\n', lines), $"line {at + 1} got {token}");
            case 3:
                var parts = lines[at].Split([' ', ','], StringSplitOptions.RemoveEmptyEntries);
                var replaced = parts.Length == 0 ? string.Empty : parts[random.Next(parts.Length)];
                lines[at] = replaced.Length == 0 ? token : lines[at].Replace(replaced, token, StringComparison.Ordinal);
                return (string.Join('\n', lines), $"line {at + 1}: '{replaced}' became {token}");
            case 4:
                var copied = random.Next(lines.Count);
                lines.Insert(at, lines[copied]);
                return (string.Join('\n', lines), $"line {copied + 1} repeated before line {at + 1}");
            case 5:
                var chars = text.ToCharArray();
                var position = random.Next(chars.Length);
                chars[position] = (char)random.Next(0, 256);
                return (new string(chars), $"character {position} became {(int)chars[position]}");
            default:
                lines[at] = lines[at].Insert(random.Next(lines[at].Length + 1), "\0");
                return (string.Join('\n', lines), $"NUL in line {at + 1}");
        }
    }
}
