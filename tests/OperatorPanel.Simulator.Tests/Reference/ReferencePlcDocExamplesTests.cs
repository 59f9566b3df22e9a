using System.Text;
using System.Text.RegularExpressions;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Simulator.Reference;

namespace OperatorPanel.Simulator.Tests.Reference;

/// <summary>
/// The reference model answers the worked examples of docs/protocol-v2.md section 5, in order on one station, exactly as
/// documented: the station and memory the section states (CPU 224, STOP enabled, 120 copy bytes, VD100 = 1111,
/// IB0-IB1 = A5 03, MB2 = 05, QB0 = 01, scans 3/2/9 ms).
/// </summary>
public sealed partial class ReferencePlcDocExamplesTests
{
    private const string NoReply = "(no reply)";

    [Fact]
    public void ReferencePlc_EveryWorkedExampleInOrder_AnswersAsDocumented()
    {
        var plc = new ReferencePlc(new HandlerConfig(new Station(1), CpuProfiles.For(CpuModel.Cpu224), allowStop: true));
        plc.Memory.WriteDoubleWord(ProtocolArea.V, 100, 1111);
        (plc.Memory.I[0], plc.Memory.I[1], plc.Memory.M[2], plc.Memory.Q[0]) = (0xA5, 0x03, 0x05, 0x01);
        plc.CompleteScan(9);
        plc.CompleteScan(2);
        plc.CompleteScan(3);
        var port = new SimulatedPlcPort(plc);

        var examples = Examples();
        foreach (var (name, pc, documented) in examples)
        {
            var replies = port.Feed(Encoding.ASCII.GetBytes(pc));

            var answer = replies.Count == 0 ? NoReply : string.Join(" ", replies.Select(r => Encoding.ASCII.GetString(r)));
            answer.Should().Be(documented, $"example {name}: {pc}");
        }

        examples.Should().HaveCountGreaterThan(25);
        plc.Mode.Should().Be(OperatingMode.Stop, "the last example is STOP");
    }

    private static List<(string Name, string Pc, string Plc)> Examples()
    {
        var dir = new DirectoryInfo(AppContext.BaseDirectory);
        while (dir is not null && !File.Exists(Path.Combine(dir.FullName, "OperatorPanel.sln")))
        {
            dir = dir.Parent;
        }

        var text = File.ReadAllText(Path.Combine(dir!.FullName, "docs", "protocol-v2.md"));
        return [.. CodeBlock().Matches(text).Select(block => block.Groups[1].Value)
            .Where(body => ExampleName().IsMatch(body))
            .Select(body => (ExampleName().Match(body).Groups[1].Value, Line(body, "PC  -> "), Line(body, "PLC -> ")))];
    }

    private static string Line(string body, string prefix) =>
        Regex.Match(body, "^" + Regex.Escape(prefix) + "(.+)$", RegexOptions.Multiline).Groups[1].Value.Trim();

    [GeneratedRegex(@"```text\n(.*?)```", RegexOptions.Singleline)]
    private static partial Regex CodeBlock();

    [GeneratedRegex(@"^example: (\S+)$", RegexOptions.Multiline)]
    private static partial Regex ExampleName();
}
