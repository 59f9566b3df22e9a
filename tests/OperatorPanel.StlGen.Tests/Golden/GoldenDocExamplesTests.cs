using System.Globalization;
using System.Text;
using System.Text.RegularExpressions;
using OperatorPanel.Core.Protocol;
using OperatorPanel.StlGen.Tests.Differential;

namespace OperatorPanel.StlGen.Tests.Golden;

/// <summary>
/// Every golden configuration, executed in the interpreter, answers the worked examples of docs/protocol-v2.md section 5
/// in order, exactly as documented, with the frames re-addressed to the configuration's station. The examples assume
/// VD100 = 16#00000457, IB0-IB1 = 16#A5 16#03, MB2 = 16#05 and QB0 = 16#01. IDENTIFY describes the documented CPU 224
/// on port 0 with example scan times, so its reply is compared with the reference model instead (the differential
/// tests prove the reference's IDENTIFY); so is error-02 on CPUs where VB8192 exists.
/// </summary>
public sealed partial class GoldenDocExamplesTests
{
    private const string NoReply = "(no reply)";

    [Theory]
    [MemberData(nameof(HandlerGoldenTests.Cases), MemberType = typeof(HandlerGoldenTests))]
    public void Handler_GoldenConfiguration_AnswersEveryWorkedExampleAsDocumented(string name)
    {
        var options = HandlerGoldenTests.OptionsFor(name);
        var harness = new DifferentialHarness(options, new Random(1));
        harness.Poke(ProtocolArea.V, 100, 0x00, 0x00, 0x04, 0x57);
        harness.Poke(ProtocolArea.I, 0, 0xA5, 0x03);
        harness.Poke(ProtocolArea.M, 2, 0x05);
        harness.Poke(ProtocolArea.Q, 0, 0x01);
        // VB8192 (example error-02) exists on the CPUs with 10240 V bytes: there the read succeeds.
        var vBeyond8192 = harness.Reference.AreaBytes(ProtocolArea.V) > 8192;

        foreach (var (example, pc, plc) in Examples().Where(e => !NotInThisHandler(e.Pc)))
        {
            var request = Readdress(pc, options.Station);
            var (stl, reference) = harness.Exchange([WireChunk.Now(Encoding.ASCII.GetBytes(request))]);
            var fromReference = example == "identify" || (example == "error-02" && vBeyond8192);
            var expected = fromReference ? reference : plc == NoReply ? "" : Readdress(plc, options.Station, request);
            stl.Should().Be(expected, $"example {example}: {request}");
        }
    }

    /// <summary>
    /// 07 STOP: the golden configurations are generated without it (they answer 05), and after it the CPU would be in
    /// STOP. READ CHANGES and READ CHANGES OF LISTS run as documented: every golden configuration has 120 copy bytes.
    /// </summary>
    private static bool NotInThisHandler(string request) =>
        FrameCodec.TryDecode(Encoding.ASCII.GetBytes(request), out var decoded, out _) && decoded.Command is (byte)CommandCode.Stop;

    /// <summary>
    /// The frame with station 1 replaced by <paramref name="station"/> (other stations, the multi-drop examples, stay)
    /// and its check redone; a reply's REQCHECK becomes that of the re-addressed <paramref name="request"/>.
    /// </summary>
    private static string Readdress(string frame, int station, string? request = null)
    {
        var last = frame.LastIndexOf('<');
        if (last > 0)
        {
            // The remains of a cut-off frame, then a frame: each re-addressed alike.
            return RemainsReaddressed(frame[..last], station) + Readdress(frame[last..], station, request);
        }

        var bytes = Encoding.ASCII.GetBytes(frame);
        if (!FrameCodec.TryDecode(bytes, out var decoded, out _))
        {
            return frame;
        }

        var to = decoded.Station == 1 ? (byte)station : decoded.Station == station ? (byte)1 : decoded.Station;
        var payload = decoded.Payload;
        if (decoded.IsReply && request is not null && FrameCodec.TryGetCheck(Encoding.ASCII.GetBytes(request[request.LastIndexOf('<')..]), out var check))
        {
            payload = payload.SetItem(1, (byte)(check >> 8)).SetItem(2, (byte)check);
        }

        return Encoding.ASCII.GetString(FrameCodec.Encode(decoded with { Station = to, Payload = payload }));
    }

    /// <summary>"&lt;0114" for station 2: "&lt;0214" (a station 2 the other way round, any other station stays).</summary>
    private static string RemainsReaddressed(string remains, int station)
    {
        var own = station.ToString("X2", CultureInfo.InvariantCulture);
        var to = remains.StartsWith("<01", StringComparison.Ordinal) ? own : remains.StartsWith("<" + own, StringComparison.Ordinal) ? "01" : null;
        return to is null || remains.Length < 3 ? remains : "<" + to + remains[3..];
    }

    private static List<(string Name, string Pc, string Plc)> Examples()
    {
        var dir = new DirectoryInfo(AppContext.BaseDirectory);
        while (dir is not null && !File.Exists(Path.Combine(dir.FullName, "OperatorPanel.sln")))
        {
            dir = dir.Parent;
        }

        var text = File.ReadAllText(Path.Combine(dir!.FullName, "docs", "protocol-v2.md"));
        var examples = new List<(string, string, string)>();
        foreach (Match block in CodeBlock().Matches(text))
        {
            var body = block.Groups[1].Value;
            var name = Regex.Match(body, @"^example: (\S+)$", RegexOptions.Multiline);
            if (name.Success)
            {
                examples.Add((name.Groups[1].Value, Line(body, "PC  -> "), Line(body, "PLC -> ")));
            }
        }

        examples.Should().HaveCountGreaterThan(15);
        return examples;
    }

    private static string Line(string body, string prefix) =>
        Regex.Match(body, "^" + Regex.Escape(prefix) + "(.+)$", RegexOptions.Multiline).Groups[1].Value.Trim();

    [GeneratedRegex(@"```text\n(.*?)```", RegexOptions.Singleline)]
    private static partial Regex CodeBlock();
}
