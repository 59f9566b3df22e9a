using System.Globalization;
using System.Text.RegularExpressions;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.TestKit.ProtocolDoc;

/// <summary>
/// The worked examples of docs/protocol.md section 5 as steps a test checks or replays: "request" and "reply" lines,
/// the one-line "frame -> frame" (or "-> silence") refusals, memory set in the text ("IB0 := 11, QB1 := 22"), and
/// "(xN)", which repeats the 4-byte item before it N times in all; frames inline in prose ("request `...`, reply `...`")
/// and the one-line frames the text sends to a compact handler are marked <see cref="Section5Step.OtherHandler"/>. The section's setup (CPU 224, station 2, the memory
/// and scan times its first paragraph gives) is the replaying test's.
/// </summary>
public static partial class ProtocolSection5
{
    /// <summary>The section's text, from its heading to section 6.</summary>
    public static string Text()
    {
        var text = File.ReadAllText(Path.Combine(Repository.Root(), "docs", "protocol.md"));
        var start = text.IndexOf("## 5. Worked examples", StringComparison.Ordinal);
        var end = start < 0 ? -1 : text.IndexOf("## 6.", start, StringComparison.Ordinal);
        return start < 0 || end < 0 ? throw new InvalidOperationException("docs/protocol.md has no section 5") : text[start..end];
    }

    public static IReadOnlyList<Section5Step> Steps()
    {
        var steps = new List<Section5Step>();
        (string Line, byte[] Frame)? pending = null;
        foreach (var raw in Text().Split('\n'))
        {
            var line = raw.TrimEnd();
            // Memory set in prose; a frame's own description ("WRITE IB0 := 01  3C 0D ...") sets nothing.
            var pokes = line.Contains("3C ", StringComparison.Ordinal) ? [] : Pokes(line);
            if (pokes.Count > 0)
            {
                steps.Add(new(line, pokes, null, null, false, false));
            }

            if (FramePrefix("request").Match(line) is { Success: true } r)
            {
                Finish(pending);
                pending = (line, Frame(r.Groups[1].Value));
            }
            else if (FramePrefix("reply").Match(line) is { Success: true } a)
            {
                var (requestLine, request) = pending ?? throw new FormatException($"a reply without its request: {line}");
                steps.Add(new(requestLine + " / " + line, [], request, Frame(a.Groups[1].Value), false, false));
                pending = null;
            }
            else if (OneLine().Match(line) is { Success: true } o)
            {
                Finish(pending);
                pending = null;
                var answer = o.Groups[2].Value.Trim();
                steps.Add(new(
                    line, [], Frame(o.Groups[1].Value), answer.StartsWith("3C", StringComparison.Ordinal) ? Frame(answer) : null,
                    line.Contains("bit flipped", StringComparison.Ordinal), line.Contains("compact handler", StringComparison.Ordinal)));
            }
        }

        Finish(pending);
        // Inline in prose: "A compact handler (...): request `3C ...`, reply `3C ...`".
        foreach (Match m in Inline().Matches(Text()))
        {
            steps.Add(new(m.Value.ReplaceLineEndings(" "), [], Frame(m.Groups[1].Value), Frame(m.Groups[2].Value), false, true));
        }

        return steps;
    }

    /// <summary>Every request line has its reply line right after it.</summary>
    private static void Finish((string Line, byte[] Frame)? pending)
    {
        if (pending is { } p)
        {
            throw new FormatException($"a request without its reply: {p.Line}");
        }
    }

    /// <summary>"IB0 := 11", "VB102 := 44" in a line of text.</summary>
    private static List<(ProtocolArea, int, byte)> Pokes(string line) =>
    [
        .. Poke().Matches(line).Select(m => (
            m.Groups[1].Value switch { "I" => ProtocolArea.I, "Q" => ProtocolArea.Q, "M" => ProtocolArea.M, "V" => ProtocolArea.V, _ => ProtocolArea.SM },
            int.Parse(m.Groups[2].Value, CultureInfo.InvariantCulture), byte.Parse(m.Groups[3].Value, NumberStyles.HexNumber, CultureInfo.InvariantCulture))),
    ];

    /// <summary>Hex bytes; '|' field marks ignored; "(xN)" repeats the 4 bytes before it N times in all.</summary>
    private static byte[] Frame(string text)
    {
        var bytes = new List<byte>();
        foreach (var token in text.Replace("|", " ", StringComparison.Ordinal).Split(' ', StringSplitOptions.RemoveEmptyEntries))
        {
            if (Repeat().Match(token) is { Success: true } x)
            {
                var item = bytes[^4..];
                for (var i = 1; i < int.Parse(x.Groups[1].Value, CultureInfo.InvariantCulture); i++)
                {
                    bytes.AddRange(item);
                }

                continue;
            }

            bytes.Add(byte.Parse(token, NumberStyles.HexNumber, CultureInfo.InvariantCulture));
        }

        return [.. bytes];
    }

    private static Regex FramePrefix(string word) => new($@"^{word}\s+(3C(?: \|?\s*[0-9A-F]{{2}}| \|)*)");

    /// <summary>A frame (with "(xN)" repeats), "->", then a frame or "silence".</summary>
    [GeneratedRegex(@"(3C(?: (?:[0-9A-F]{2}|\(x\d+\)))+)\s+->\s+((?:3C(?: [0-9A-F]{2})+)|silence)")]
    private static partial Regex OneLine();

    [GeneratedRegex(@"request `(3C[0-9A-F ]+)`, reply\s+`(3C[0-9A-F ]+)`")]
    private static partial Regex Inline();

    [GeneratedRegex(@"^\(x(\d+)\)$")]
    private static partial Regex Repeat();

    [GeneratedRegex(@"\b(I|Q|M|V|SM)B(\d+) := ([0-9A-F]{2})\b")]
    private static partial Regex Poke();
}
