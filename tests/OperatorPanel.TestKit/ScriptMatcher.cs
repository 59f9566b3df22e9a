using System.Globalization;

namespace OperatorPanel.TestKit;

/// <summary>Matches written bytes against a request line and renders response lines.</summary>
internal static class ScriptMatcher
{
    public static bool TryMatch(IReadOnlyList<ScriptElement> expected, ReadOnlySpan<byte> actual, Dictionary<string, byte[]> captures, out string problem)
    {
        var at = 0;
        var captured = new Dictionary<string, byte[]>();
        foreach (var element in expected)
        {
            var width = element is ScriptElement.Capture ? 2 : 1;
            if (at + width > actual.Length)
            {
                problem = $"too short: {actual.Length} bytes";
                return false;
            }

            switch (element)
            {
                case ScriptElement.Literal literal when actual[at] != literal.Value:
                    problem = $"byte {at} is {actual[at]:X2}, expected {literal.Value:X2}";
                    return false;
                case ScriptElement.Capture capture:
                    captured[capture.Name] = actual.Slice(at, 2).ToArray();
                    break;
                case ScriptElement.Bcc:
                    throw new FormatException("{bcc} is for responses; match a request's BCC with ?? ??");
            }

            at += width;
        }

        if (at != actual.Length)
        {
            problem = $"too long: {actual.Length} bytes, expected {at}";
            return false;
        }

        foreach (var (name, value) in captured)
        {
            captures[name] = value;
        }

        problem = "";
        return true;
    }

    public static byte[] Render(ScriptStep step, Dictionary<string, byte[]> captures)
    {
        var bytes = new List<byte>();
        foreach (var element in step.Elements)
        {
            switch (element)
            {
                case ScriptElement.Literal literal:
                    bytes.Add(literal.Value);
                    break;
                case ScriptElement.Capture capture:
                    bytes.AddRange(captures.TryGetValue(capture.Name, out var value)
                        ? value
                        : throw new FormatException($"script line {step.LineNumber}: {{{capture.Name}}} was never captured"));
                    break;
                case ScriptElement.Bcc:
                    bytes.AddRange(BlockCheck(bytes));
                    break;
                default:
                    throw new FormatException($"script line {step.LineNumber}: ?? is for requests");
            }
        }

        return [.. bytes];
    }

    /// <summary>Protocol BCC (docs/protocol-v2.md): XOR of the characters after the last '&lt;', as two hex digits.</summary>
    private static byte[] BlockCheck(List<byte> sofar)
    {
        var start = sofar.LastIndexOf((byte)'<') + 1;
        var bcc = sofar.Skip(start).Aggregate(0, (acc, b) => acc ^ b);
        return System.Text.Encoding.ASCII.GetBytes(bcc.ToString("X2", CultureInfo.InvariantCulture));
    }
}
