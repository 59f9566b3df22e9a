using System.Text;

namespace OperatorPanel.StlGen.Emit;

/// <summary>
/// Text made of whole lines, each ended by CRLF (what Micro/WIN and Windows Notepad expect), ASCII only. Generated
/// text is ours, so a character outside 16#20-16#7E is a programming error and throws.
/// </summary>
internal sealed class LineWriter
{
    private const string LineEnd = "\r\n";
    private readonly StringBuilder _text = new();

    public void Line(string line)
    {
        foreach (var ch in line)
        {
            if (ch is < ' ' or > '~' && ch != '\t')
            {
                throw new ArgumentException($"not printable ASCII: U+{(int)ch:X4} in \"{line}\"", nameof(line));
            }
        }

        _text.Append(line).Append(LineEnd);
    }

    /// <summary>
    /// A line of the user's exported program, copied as it is: its characters stand for the bytes of the user's Windows
    /// code page (read as Latin-1) and are written back as the same bytes, so names and comments with umlauts survive.
    /// </summary>
    public void Copied(string line)
    {
        if (line.AsSpan().IndexOfAny('\r', '\n') >= 0)
        {
            throw new ArgumentException("a copied line holds no line end", nameof(line));
        }

        _text.Append(line).Append(LineEnd);
    }

    public override string ToString() => _text.ToString();
}
