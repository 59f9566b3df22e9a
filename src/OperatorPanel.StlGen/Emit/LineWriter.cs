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

    public override string ToString() => _text.ToString();
}
