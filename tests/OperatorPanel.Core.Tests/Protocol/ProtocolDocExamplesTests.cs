using System.Text;
using System.Text.RegularExpressions;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Protocol.V1;

namespace OperatorPanel.Core.Tests.Protocol;

/// <summary>
/// Every example block of docs/protocol-v2.md ("example: name", then "PC  -> frame" and "PLC -> frame" or
/// "PLC -> (no reply)") must decode with a valid check and equal what the codecs encode for the stated message, every
/// reply carrying the REQCHECK of its request.
/// </summary>
public sealed partial class ProtocolDocExamplesTests
{
    private const string NoReply = "(no reply)";
    private static readonly Station One = new(1);

    /// <summary>COUNT 20: VD0, VD8 … VD144 and VB160-VB162, 79 bytes: 2 x 79 + 4 x 20 = 238 &gt; 237.</summary>
    private static readonly byte[] DataRuleItems =
        [20, .. Enumerable.Range(0, 19).SelectMany(i => new byte[] { 0x04, 0x00, (byte)(i * 8), 4 }), 0x04, 0x00, 0xA0, 3];

    private static readonly ReadListRequest RestartedReadList = new(One, 0x1D, 1);

    /// <summary>The stated request and reply of each example; null reply = silence.</summary>
    private static readonly Dictionary<string, (byte[] Request, byte[]? Reply)> Stated = new()
    {
        ["identify"] = Exchange(
            new IdentifyRequest(One, 0x07),
            new IdentifyResponse(One, 0x07, 2, 1, 3, 1, 0x3C, 116, 5, 0x20, 1, 3, 2, 9, 0, 7764, 428, 7, 120)),
        ["read-multi"] = Exchange(
            new ReadRequest(One, 0x08, [new(ProtocolArea.V, 100, 4), new(ProtocolArea.I, 0, 2), new(ProtocolArea.M, 2, 1)]),
            new ReadResponse(One, 0x08, [0x00, 0x00, 0x04, 0x57, 0xA5, 0x03, 0x05])),
        ["write"] = Exchange(
            new WriteBlockRequest(One, 0x09, ProtocolArea.V, 104, [0x00, 0x3C]),
            new WriteBlockResponse(One, 0x09, [0x00, 0x3C])),
        ["write-bit-set"] = Exchange(new WriteBitRequest(One, 0x0A, ProtocolArea.Q, 0, 5, true), new WriteBitResponse(One, 0x0A, 0x21)),
        ["write-bit-reset"] = Exchange(new WriteBitRequest(One, 0x0B, ProtocolArea.Q, 0, 5, false), new WriteBitResponse(One, 0x0B, 0x01)),
        ["error-02"] = Refused(new ReadRequest(One, 0x0C, [new(ProtocolArea.V, 8192, 1)]), ProtocolError.AddressOutOfRange),
        ["error-03"] = Refused(new WriteBlockRequest(One, 0x0D, ProtocolArea.I, 0, [0xFF]), ProtocolError.NotWritable),
        ["error-04"] = RawRefused(0x0E, 0x02, [0x00], ProtocolError.BadLength),
        ["error-04-data"] = RawRefused(0x12, 0x02, DataRuleItems, ProtocolError.BadLength),
        ["error-05"] = RawRefused(0x0F, 0x0A, [], ProtocolError.UnknownCommand),
        ["error-06"] = RawRefused(0x10, 0x04, [0x03, 0x00, 0x02, 0x08, 0x01], ProtocolError.BadParameter),
        ["define-list"] = Exchange(
            new DefineListRequest(One, 0x13, 1, [new(ProtocolArea.V, 100, 4), new(ProtocolArea.M, 2, 1)]),
            new DefineListResponse(One, 0x13)),
        ["read-list"] = Exchange(new ReadListRequest(One, 0x14, 1), new ReadListResponse(One, 0x14, [0x00, 0x00, 0x04, 0x57, 0x05])),
        ["error-07"] = Refused(new ReadListRequest(One, 0x15, 2), ProtocolError.ListNotDefined),
        ["read-changes-first"] = Exchange(
            new ReadChangesRequest(One, 0x16, 1, Full: false), ReadChangesResponse.Whole(One, 0x16, [0x00, 0x00, 0x04, 0x57, 0x05])),
        ["read-changes-idle"] = Exchange(new ReadChangesRequest(One, 0x17, 1, Full: false), ReadChangesResponse.Pairs(One, 0x17, [])),
        ["write-bit-m2"] = Exchange(new WriteBitRequest(One, 0x18, ProtocolArea.M, 2, 1, true), new WriteBitResponse(One, 0x18, 0x07)),
        ["read-changes-pairs"] = Exchange(
            new ReadChangesRequest(One, 0x19, 1, Full: false), ReadChangesResponse.Pairs(One, 0x19, [new ChangedByte(4, 0x07)])),
        ["write-vd100"] = Exchange(
            new WriteBlockRequest(One, 0x1A, ProtocolArea.V, 100, [0x00, 0x01, 0x11, 0x70]),
            new WriteBlockResponse(One, 0x1A, [0x00, 0x01, 0x11, 0x70])),
        ["read-changes-fallback"] = Exchange(
            new ReadChangesRequest(One, 0x1B, 1, Full: false), ReadChangesResponse.Whole(One, 0x1B, [0x00, 0x01, 0x11, 0x70, 0x07])),
        ["read-changes-full"] = Exchange(
            new ReadChangesRequest(One, 0x1C, 1, Full: true), ReadChangesResponse.Whole(One, 0x1C, [0x00, 0x01, 0x11, 0x70, 0x07])),
        ["define-list-2"] = Exchange(
            new DefineListRequest(One, 0x20, 2, [new(ProtocolArea.I, 0, 2), new(ProtocolArea.V, 104, 2)]), new DefineListResponse(One, 0x20)),
        ["read-changes-list-2"] = Exchange(
            new ReadChangesRequest(One, 0x21, 2, Full: false), ReadChangesResponse.Whole(One, 0x21, [0xA5, 0x03, 0x00, 0x3C])),
        ["read-changes-of-lists-idle"] = Exchange(
            new ReadChangesOfListsRequest(One, 0x22, 0b0011), new ReadChangesOfListsResponse(One, 0x22, [ListChanges.Pairs(1, []), ListChanges.Pairs(2, [])])),
        ["write-v100-v105"] = Exchange(
            new WriteBlockRequest(One, 0x23, ProtocolArea.V, 100, [0x00, 0x00, 0x04, 0x57, 0x00, 0x41]),
            new WriteBlockResponse(One, 0x23, [0x00, 0x00, 0x04, 0x57, 0x00, 0x41])),
        ["read-changes-of-lists-reread"] = Exchange(
            new ReadChangesOfListsRequest(One, 0x24, 0b0011),
            new ReadChangesOfListsResponse(One, 0x24, [ListChanges.RereadList(1), ListChanges.Pairs(2, [new ChangedByte(3, 0x41)])])),
        ["read-changes-after-reread"] = Exchange(
            new ReadChangesRequest(One, 0x25, 1, Full: false), ReadChangesResponse.Whole(One, 0x25, [0x00, 0x00, 0x04, 0x57, 0x07])),
        ["restart"] = (
            [.. "<0114"u8, .. RequestCodec.Encode(RestartedReadList)],
            ResponseCodec.Encode(new ReadListResponse(One, 0x1D, [0x00, 0x00, 0x04, 0x57, 0x07]), RestartedReadList)),
        ["silence-early-other-station"] = ([.. "<0211"u8, .. RequestCodec.Encode(new ReadListRequest(One, 0x1F, 1))], null),
        ["silence-bad-check"] = ("<010701dl`m>"u8.ToArray(), null),
        ["silence-other-station"] = (RequestCodec.Encode(new IdentifyRequest(new Station(2), 0x11)), null),
        ["silence-overheard-reply"] = (RawRefused(0x0F, 0x0A, [], ProtocolError.UnknownCommand).Reply!, null),
        ["silence-v1-probe"] = (V1IdentifyProbe.Encode(One, 0x07), null),
        ["stop"] = Exchange(new StopRequest(One, 0x1E), new StopResponse(One, 0x1E)),
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
    public void Doc_EveryFrameFromItsLastStart_DecodesWithAValidCheckExceptTheBadCheckAndV1Examples()
    {
        foreach (var (name, pc, plc) in Examples())
        {
            foreach (var line in new[] { pc, plc }.Where(f => f != NoReply))
            {
                var frame = line[line.LastIndexOf('<')..];
                var ok = FrameCodec.TryDecode(Encoding.ASCII.GetBytes(frame), out _, out var error);
                var expected = name switch
                {
                    "silence-bad-check" => FrameError.ChecksumMismatch,
                    "silence-v1-probe" => FrameError.TooShort,
                    _ => FrameError.None,
                };
                error.Should().Be(expected, $"example {name} frame {frame}");
                ok.Should().Be(expected == FrameError.None);
            }
        }
    }

    [Fact]
    public void Doc_V1ReplyInSection9_IsWhatTheProbeRecognises()
    {
        var text = File.ReadAllText(Path.Combine(RepositoryRoot(), "docs", "protocol-v2.md"));
        var reply = Regex.Match(text, "`(<0107810001[0-9A-F]+>)`").Groups[1].Value;

        V1IdentifyProbe.TryDecodeReply(Encoding.ASCII.GetBytes(reply), One, 0x07, out var version).Should().BeTrue(reply);
        version.Should().Be(1);
    }

    [Fact]
    public void Doc_DataRuleExample_IsRefusedWithBadLengthByTheParser()
    {
        var frame = new FreeportFrame(1, 0x12, 0x02, [.. DataRuleItems]);
        DataRuleItems.Skip(1).Chunk(4).Sum(item => item[3]).Should().Be(79);

        RequestCodec.TryParse(frame, new FakeTarget(), out _, out var error).Should().BeFalse();

        error.Should().Be(ProtocolError.BadLength);
    }

    private static (byte[] Request, byte[]? Reply) Exchange(PlcRequest request, PlcResponse response) =>
        (RequestCodec.Encode(request), ResponseCodec.Encode(response, request));

    private static (byte[] Request, byte[]? Reply) Refused(PlcRequest request, ProtocolError error) =>
        Exchange(request, new ErrorResponse(One, request.Sequence, request.Command, error));

    /// <summary>A request the codec would not encode (it breaks a rule), and its error reply carrying its check.</summary>
    private static (byte[] Request, byte[]? Reply) RawRefused(byte sequence, byte command, byte[] payload, ProtocolError error)
    {
        var request = new FreeportFrame(1, sequence, command, [.. payload]);
        var reply = new ErrorResponse(One, sequence, (CommandCode)command, error) { RequestCheck = FrameCodec.CheckOf(request) };
        return (FrameCodec.Encode(request), ResponseCodec.Encode(reply));
    }

    private static List<(string Name, string Pc, string Plc)> Examples()
    {
        var text = File.ReadAllText(Path.Combine(RepositoryRoot(), "docs", "protocol-v2.md"));
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
