using System.Globalization;
using System.Text.RegularExpressions;
using OperatorPanel.Core.Addressing;
using OperatorPanel.StlGen.Tests.Golden;

namespace OperatorPanel.StlGen.Tests.Handler;

/// <summary>Scans the generated text: every address lies inside the CPU's ranges, and V only inside the reserved bytes.</summary>
public sealed partial class HandlerOperandTests
{
    [Theory]
    [MemberData(nameof(HandlerGoldenTests.Cases), MemberType = typeof(HandlerGoldenTests))]
    public void Generate_EveryOperand_LiesInsideTheCpuRanges(string name)
    {
        var options = HandlerGoldenTests.OptionsFor(name);
        var result = HandlerGenerator.Generate(options);
        var problems = new List<string>();

        foreach (var (text, area, first, last) in Addresses(result.AwlText))
        {
            if (!options.Cpu.TryGetArea(area, out var range) || last > range.LastByte)
            {
                problems.Add(text);
            }
        }

        problems.Should().BeEmpty();
    }

    [Theory]
    [MemberData(nameof(HandlerGoldenTests.Cases), MemberType = typeof(HandlerGoldenTests))]
    public void Generate_VOperands_UseExactlyTheReservedRange(string name)
    {
        var result = HandlerGenerator.Generate(HandlerGoldenTests.OptionsFor(name));
        var stats = result.Stats!;
        var used = new SortedSet<int>();

        // &VB0 is the V area's start, to which a READ or WRITE of V adds its OFFSET: an area pointer, not a use of VB0.
        foreach (var (_, _, first, last) in Addresses(result.AwlText).Where(a => a.Area == MemoryArea.V && a.Text != "&VB0"))
        {
            for (var b = first; b <= last; b++)
            {
                used.Add(b);
            }
        }

        used.Min.Should().Be(stats.FirstVByte);
        used.Max.Should().Be(stats.LastVByte);
        stats.VBytes.Should().Be(272);
    }

    [Fact]
    public void Generate_Blocks_AreTheOnesTheStatsReport()
    {
        var result = HandlerGenerator.Generate(HandlerGoldenTests.Cpu226Port1Station17);

        result.Stats!.Blocks.Select(b => b.NumberText).Should().Equal("SBR127", "INT125", "INT126", "INT127");
        result.Stats.InterruptEvents.Should().Equal(24, 10, 26);
        Regex.Matches(result.AwlText, @"(?:ATCH|DTCH)\s+(?:\w+, )?(\d+)").Select(m => int.Parse(m.Groups[1].Value, CultureInfo.InvariantCulture))
            .Distinct().Should().BeEquivalentTo([24, 10, 26]);
    }

    private static IEnumerable<(string Text, MemoryArea Area, int First, int Last)> Addresses(string awl)
    {
        var instructions = string.Join("\r\n", awl.Split("\r\n").Where(l => !l.StartsWith("//", StringComparison.Ordinal) && !l.StartsWith("Network", StringComparison.Ordinal) && !l.StartsWith("TITLE=", StringComparison.Ordinal)));
        foreach (Match m in Operand().Matches(instructions))
        {
            var text = m.Value;
            var bare = text.TrimStart('&');
            if (!PlcAddress.TryParse(bare, out var address, out _))
            {
                continue;
            }

            yield return (text, address.Area, address.ByteOffset, address.LastByte);
        }
    }

    [GeneratedRegex(@"(?<=[\s,])&?(?:SM|V|I|Q|M)(?:B|W|D)?\d+(?:\.\d)?(?=,|\r|$| )", RegexOptions.Multiline)]
    private static partial Regex Operand();
}
