using System.Text;
using System.Text.RegularExpressions;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Core.Tests.Protocol;

/// <summary>
/// Every example block of docs/protocol.md ("example: name", then "PC  -> frame" and "PLC -> frame" or
/// "PLC -> (no reply)") must decode with a valid block check and equal what the codecs encode for the stated message.
/// </summary>
public sealed partial class ProtocolDocExamplesTests
{
    private const string NoReply = "(no reply)";
    private static readonly Station One = new(1);

    /// <summary>COUNT 20: VD0, VD8 … VD144 and VB160-VB165, 82 bytes: 2 x 82 + 4 x 20 = 244 &gt; 243.</summary>
    private static readonly byte[] DataRuleItems =
        [20, .. Enumerable.Range(0, 19).SelectMany(i => new byte[] { 0x04, 0x00, (byte)(i * 8), 4 }), 0x04, 0x00, 0xA0, 6];

    /// <summary>The stated request and reply of each example; null reply = silence.</summary>
    private static readonly Dictionary<string, (byte[] Request, byte[]? Reply)> Stated = new()
    {
        ["identify"] = (
            RequestCodec.Encode(new IdentifyRequest(One, 0x07)),
            ResponseCodec.Encode(new IdentifyResponse(One, 0x07, 2, 1, 3, 1, 0x3C, 116, 5, 0x20, 1, 3, 2, 9, 0, 7764, 428, 2, 120))),
        ["read-multi"] = (
            RequestCodec.Encode(new ReadRequest(One, 0x08, [new(ProtocolArea.V, 100, 4), new(ProtocolArea.I, 0, 2), new(ProtocolArea.M, 2, 1)])),
            ResponseCodec.Encode(new ReadResponse(One, 0x08, [0x00, 0x00, 0x04, 0x57, 0xA5, 0x03, 0x05]))),
        ["write"] = (
            RequestCodec.Encode(new WriteBlockRequest(One, 0x09, ProtocolArea.V, 104, [0x00, 0x3C])),
            ResponseCodec.Encode(new WriteBlockResponse(One, 0x09, [0x00, 0x3C]))),
        ["write-bit-set"] = (
            RequestCodec.Encode(new WriteBitRequest(One, 0x0A, ProtocolArea.Q, 0, 5, true)),
            ResponseCodec.Encode(new WriteBitResponse(One, 0x0A, 0x21))),
        ["write-bit-reset"] = (
            RequestCodec.Encode(new WriteBitRequest(One, 0x0B, ProtocolArea.Q, 0, 5, false)),
            ResponseCodec.Encode(new WriteBitResponse(One, 0x0B, 0x01))),
        ["error-02"] = (
            RequestCodec.Encode(new ReadRequest(One, 0x0C, [new(ProtocolArea.V, 8192, 1)])),
            Error(0x0C, CommandCode.Read, ProtocolError.AddressOutOfRange)),
        ["error-03"] = (
            RequestCodec.Encode(new WriteBlockRequest(One, 0x0D, ProtocolArea.I, 0, [0xFF])),
            Error(0x0D, CommandCode.Write, ProtocolError.NotWritable)),
        ["error-04"] = (Raw(0x0E, 0x02, 0x00), Error(0x0E, CommandCode.Read, ProtocolError.BadLength)),
        ["error-04-data"] = (Raw(0x12, 0x02, DataRuleItems), Error(0x12, CommandCode.Read, ProtocolError.BadLength)),
        ["error-05"] = (Raw(0x0F, 0x07), Error(0x0F, (CommandCode)0x07, ProtocolError.UnknownCommand)),
        ["error-06"] = (Raw(0x10, 0x04, 0x03, 0x00, 0x02, 0x08, 0x01), Error(0x10, CommandCode.WriteBit, ProtocolError.BadParameter)),
        ["define-list"] = (
            RequestCodec.Encode(new DefineListRequest(One, 0x13, 1, [new(ProtocolArea.V, 100, 4), new(ProtocolArea.M, 2, 1)])),
            ResponseCodec.Encode(new DefineListResponse(One, 0x13))),
        ["read-list"] = (
            RequestCodec.Encode(new ReadListRequest(One, 0x14, 1)),
            ResponseCodec.Encode(new ReadListResponse(One, 0x14, [0x00, 0x00, 0x04, 0x57, 0x05]))),
        ["error-07"] = (
            RequestCodec.Encode(new ReadListRequest(One, 0x15, 2)),
            Error(0x15, CommandCode.ReadList, ProtocolError.ListNotDefined)),
        ["silence-bad-bcc"] = ("<01070108>"u8.ToArray(), null),
        ["silence-other-station"] = (RequestCodec.Encode(new IdentifyRequest(new Station(2), 0x11)), null),
        ["silence-overheard-reply"] = (Error(0x0F, (CommandCode)0x07, ProtocolError.UnknownCommand), null),
    };

    [Fact]
    public void Doc_EveryExample_IsStatedHereAndEveryStatedExampleIsInTheDoc()
    {
        Examples().Select(e => e.Name).Should().BeEquivalentTo(Stated.Keys);
    }

    [Fact]
    public void Doc_EveryExampleFrame_EqualsWhatTheCodecEncodes()
    {
        foreach (var (name, pc, plc) in Examples())
        {
            var (request, reply) = Stated[name];
            pc.Should().Be(Encoding.ASCII.GetString(request), $"example {name}, PC line");
            plc.Should().Be(reply is null ? NoReply : Encoding.ASCII.GetString(reply), $"example {name}, PLC line");
        }
    }

    [Fact]
    public void Doc_EveryFrameExceptTheBadChecksumExample_DecodesWithAValidBlockCheck()
    {
        foreach (var (name, pc, plc) in Examples())
        {
            foreach (var frame in new[] { pc, plc }.Where(f => f != NoReply))
            {
                var ok = FrameCodec.TryDecode(Encoding.ASCII.GetBytes(frame), out _, out var error);
                if (name == "silence-bad-bcc")
                {
                    error.Should().Be(FrameError.ChecksumMismatch);
                }
                else
                {
                    ok.Should().BeTrue($"example {name} frame {frame} ({error})");
                }
            }
        }
    }

    [Fact]
    public void Doc_DataRuleExample_IsRefusedWithBadLengthByTheParser()
    {
        var frame = new FreeportFrame(1, 0x12, 0x02, [.. DataRuleItems]);

        RequestCodec.TryParse(frame, new FakeTarget(), out _, out var error).Should().BeFalse();

        error.Should().Be(ProtocolError.BadLength);
    }

    private static byte[] Raw(byte sequence, byte command, params byte[] payload) =>
        FrameCodec.Encode(new FreeportFrame(1, sequence, command, [.. payload]));

    private static byte[] Error(byte sequence, CommandCode command, ProtocolError error) =>
        ResponseCodec.Encode(new ErrorResponse(One, sequence, command, error));

    private static List<(string Name, string Pc, string Plc)> Examples()
    {
        var text = File.ReadAllText(Path.Combine(RepositoryRoot(), "docs", "protocol.md"));
        var examples = new List<(string, string, string)>();
        foreach (Match block in CodeBlock().Matches(text))
        {
            var body = block.Groups[1].Value;
            var name = Regex.Match(body, @"^example: (\S+)$", RegexOptions.Multiline);
            if (!name.Success)
            {
                continue;
            }

            var pc = Regex.Match(body, @"^PC  -> (.+)$", RegexOptions.Multiline).Groups[1].Value.Trim();
            var plc = Regex.Match(body, @"^PLC -> (.+)$", RegexOptions.Multiline).Groups[1].Value.Trim();
            examples.Add((name.Groups[1].Value, pc, plc));
        }

        examples.Should().NotBeEmpty();
        return examples;
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

    [GeneratedRegex(@"```text\n(.*?)```", RegexOptions.Singleline)]
    private static partial Regex CodeBlock();
}
