using System.Collections.Immutable;
using System.Globalization;

namespace OperatorPanel.TestKit;

/// <summary>Reads the annotated script of <see cref="ScriptedTransport"/>; a malformed script is a test bug and throws.</summary>
internal static class ScriptParser
{
    public static ImmutableArray<ScriptStep> Parse(string script)
    {
        var steps = ImmutableArray.CreateBuilder<ScriptStep>();
        var lines = script.Split('\n');
        for (var i = 0; i < lines.Length; i++)
        {
            var text = lines[i].Split("//", 2)[0].Trim();
            if (text.Length == 0)
            {
                continue;
            }

            var body = text[1..].Trim();
            steps.Add(text[0] switch
            {
                '>' => new ScriptStep(ScriptStepKind.Request, Tokens(body, i + 1), i + 1, text),
                '<' when body == "no response" => new ScriptStep(ScriptStepKind.NoResponse, [], i + 1, text),
                '<' => new ScriptStep(ScriptStepKind.Response, Tokens(body, i + 1), i + 1, text),
                _ => throw new FormatException($"script line {i + 1}: starts with neither '>' nor '<': {text}"),
            });
        }

        return steps.ToImmutable();
    }

    private static ImmutableArray<ScriptElement> Tokens(string body, int line)
    {
        var tokens = ImmutableArray.CreateBuilder<ScriptElement>();
        var at = 0;
        while (at < body.Length)
        {
            var c = body[at];
            if (char.IsWhiteSpace(c))
            {
                at++;
            }
            else if (c == '"')
            {
                var end = body.IndexOf('"', at + 1);
                Require(end > at, line, "unterminated string");
                tokens.AddRange(body[(at + 1)..end].Select(ch => new ScriptElement.Literal((byte)ch)));
                at = end + 1;
            }
            else if (c == '{')
            {
                var end = body.IndexOf('}', at);
                Require(end > at, line, "unterminated {name}");
                var name = body[(at + 1)..end];
                tokens.Add(name == "bcc" ? new ScriptElement.Bcc() : new ScriptElement.Capture(name));
                at = end + 1;
            }
            else
            {
                Require(at + 1 < body.Length, line, $"lone hex digit at column {at + 1}");
                var pair = body.Substring(at, 2);
                tokens.Add(pair == "??" ? new ScriptElement.AnyByte() : new ScriptElement.Literal(HexByte(pair, line)));
                at += 2;
            }
        }

        return tokens.ToImmutable();
    }

    private static byte HexByte(string pair, int line) =>
        byte.TryParse(pair, NumberStyles.AllowHexSpecifier, CultureInfo.InvariantCulture, out var value)
            ? value
            : throw new FormatException($"script line {line}: \"{pair}\" is not a hex byte");

    private static void Require(bool condition, int line, string problem)
    {
        if (!condition)
        {
            throw new FormatException($"script line {line}: {problem}");
        }
    }
}
