using System.Globalization;
using System.Text.RegularExpressions;
using OperatorPanel.Core.Protocol.V3;

namespace OperatorPanel.Core.Tests.Protocol;

/// <summary>
/// The worked examples of docs/protocol.md section 5 (protocol v3) are frames a stranger copies into a client or a
/// handler: each request must be a valid v3 request (LEN, check, STATION, CMD) and each reply the valid reply to the
/// request before it (its check, STATUS bit 7, REQCHECK = the request's last two bytes), except the frames the text
/// itself calls corrupted.
/// </summary>
public sealed partial class V3DocExamplesTests
{
    [Fact]
    public void Section5_EveryRequestAndReply_DecodesAndEveryReplyAnswersItsRequest()
    {
        var pairs = Pairs(Section5()).ToList();

        pairs.Should().HaveCountGreaterThan(20, "section 5 has IDENTIFY, READ, WRITE, WRITE BITS, the list and the refusals");
        foreach (var (line, request, reply) in pairs)
        {
            Codec.TryDecodeRequest(request, out _, out var requestError).Should().BeTrue($"{line}: request {requestError}");
            if (reply is not null)
            {
                Codec.TryDecodeReplyTo(reply, request, out _, out var replyError).Should().BeTrue($"{line}: reply {replyError}");
            }
        }
    }

    [Fact]
    public void Section5_TheFrameWithOneBitFlipped_FailsItsCheck()
    {
        var flipped = Regex.Match(Section5(), @"one bit flipped[^\n]*?((?:[0-9A-F]{2} )+)\s*->").Groups[1].Value;

        Codec.TryDecodeRequest(Hex(flipped), out _, out var error).Should().BeFalse();
        error.Should().Be(DecodeError.CheckMismatch);
    }

    /// <summary>"request ..." then "reply ..." lines, and the one-line "... &lt;frame&gt; -> &lt;frame&gt;" refusals and STOP; a line naming the flipped bit is left out.</summary>
    private static IEnumerable<(string Line, byte[] Request, byte[]? Reply)> Pairs(string section)
    {
        byte[]? request = null;
        string? requestLine = null;
        foreach (var raw in section.Split('\n'))
        {
            var line = raw.TrimEnd();
            if (line.Contains("(x", StringComparison.Ordinal) || line.Contains("bit flipped", StringComparison.Ordinal))
            {
                continue;
            }

            if (FramePrefix("request").Match(line) is { Success: true } r)
            {
                (request, requestLine) = (Hex(r.Groups[1].Value), line);
                yield return (line, request, null);
            }
            else if (FramePrefix("reply").Match(line) is { Success: true } a && request is not null)
            {
                yield return (requestLine + " / " + line, request, Hex(a.Groups[1].Value));
            }
            else if (OneLine().Match(line) is { Success: true } o)
            {
                var one = Hex(o.Groups[1].Value);
                var answer = o.Groups[2].Value.Trim();
                yield return (line, one, answer.StartsWith("3C", StringComparison.Ordinal) ? Hex(answer) : null);
            }
        }
    }

    private static Regex FramePrefix(string word) => new($@"^{word}\s+(3C(?: \|?\s*[0-9A-F]{{2}}| \|)*)");

    /// <summary>A frame, "->", then a frame or words ("silence ...").</summary>
    [GeneratedRegex(@"(3C(?: [0-9A-F]{2})+)\s+->\s+((?:3C(?: [0-9A-F]{2})+)|silence)")]
    private static partial Regex OneLine();

    /// <summary>Hex bytes separated by spaces, '|' field marks ignored.</summary>
    private static byte[] Hex(string text) =>
        [.. text.Replace("|", " ", StringComparison.Ordinal).Split(' ', StringSplitOptions.RemoveEmptyEntries)
            .Select(h => byte.Parse(h, NumberStyles.HexNumber, CultureInfo.InvariantCulture))];

    private static string Section5()
    {
        var text = File.ReadAllText(Path.Combine(RepositoryRoot(), "docs", "protocol.md"));
        var start = text.IndexOf("## 5. Worked examples", StringComparison.Ordinal);
        var end = text.IndexOf("## 6.", start, StringComparison.Ordinal);
        start.Should().BePositive("docs/protocol.md has section 5");
        return text[start..end];
    }

    private static string RepositoryRoot()
    {
        var dir = new DirectoryInfo(AppContext.BaseDirectory);
        while (dir is not null && !File.Exists(Path.Combine(dir.FullName, "OperatorPanel.sln")))
        {
            dir = dir.Parent;
        }

        return dir?.FullName ?? throw new InvalidOperationException("OperatorPanel.sln not found above " + AppContext.BaseDirectory);
    }
}
