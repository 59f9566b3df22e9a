using OperatorPanel.Core.Cpu;
using OperatorPanel.StlGen.Options;

namespace OperatorPanel.StlGen.Tests;

public sealed class HandlerSizeTests
{
    [Fact]
    public void Estimate_OneThousandInstructions_IsFourToSevenThousandBytes()
    {
        var size = new HandlerSize(1000, 300, CpuProfiles.For(CpuModel.Cpu226));

        (size.LowBytes, size.HighBytes, size.ProgramMemoryBytes).Should().Be((4000, 7000, 16384));
        size.EstimateText.Should().Be("4000-7000 bytes (4-7 bytes an instruction)");
        size.ProgramMemoryText.Should().Be("16384 bytes on the CPU 226 (with run mode edit; 24576 without)");
        size.ExceedsHalfOfProgramMemory.Should().BeFalse();
        size.Warning.Should().BeNull();
    }

    [Theory]
    [InlineData(585, false)] // 4095 bytes at most: under half of 8192
    [InlineData(586, true)] // 4102 bytes: over half
    public void ExceedsHalfOfProgramMemory_AroundHalfACpu224_WarnsOnlyAbove(int instructions, bool warns)
    {
        var size = new HandlerSize(instructions, 10, CpuProfiles.For(CpuModel.Cpu224));

        size.ExceedsHalfOfProgramMemory.Should().Be(warns);
        (size.Warning is not null).Should().Be(warns);
    }

    [Fact]
    public void Warning_LowerFigureAboveTheWholeMemory_SaysItDoesNotFitAndNamesLargerCpusAndPpi()
    {
        var size = new HandlerSize(1177, 353, CpuProfiles.For(CpuModel.Cpu221));

        size.Warning.Should().Be(
            "the handler does not fit the CPU 221: its 1177 instructions take an estimated 4708-8239 bytes, more than the CPU's "
            + "4096 bytes of program memory (with run mode edit) even at the lower figure. Compile it with your program in Micro/WIN "
            + "to see the real size; where they do not fit together, use a CPU with more program memory (CPU 224 8192 bytes, "
            + "CPU 224XP 12288 bytes, CPU 226 16384 bytes), or reach this PLC over PPI (\"protocol\": \"ppi\" in the project), "
            + "which needs no program in the PLC");
    }

    [Fact]
    public void Warning_OnTheLargestCpu_OffersPpiOnly()
    {
        var size = new HandlerSize(1177, 353, CpuProfiles.For(CpuModel.Cpu226));

        size.Warning.Should().StartWith("the handler may leave too little room on the CPU 226: its 1177 instructions take an estimated 4708-8239 bytes, "
            + "and the upper figure is more than half of the CPU's 16384 bytes of program memory (with run mode edit).")
            .And.EndWith("where they do not fit together, reach this PLC over PPI (\"protocol\": \"ppi\" in the project), which needs no program in the PLC")
            .And.NotContain("more program memory");
    }

    [Fact]
    public void Warning_FullV3HandlerOnACpu221_OffersTheCompactHandlerFirstWithItsSize()
    {
        var full = HandlerGenerator.Generate(new HandlerOptions { Cpu = CpuProfiles.For(CpuModel.Cpu221), Station = 2 }).Stats!.Size;
        var compact = HandlerGenerator.Generate(new HandlerOptions { Cpu = CpuProfiles.For(CpuModel.Cpu221), Station = 2, Compact = true }).Stats!.Size;

        full.CompactInstructions.Should().Be(compact.Instructions);
        full.WarningAdvice.Should().Contain(
            $"where they do not fit together, use the compact handler (the wizard's \"Compact handler\", \"compact\": true in the project or --compact: "
            + $"IDENTIFY, READ, WRITE, WRITE BITS; {compact.Instructions} instructions, estimated {compact.LowBytes}-{compact.HighBytes} bytes), "
            + "use a CPU with more program memory");
        compact.Warning.Should().BeNull("the compact handler fits a CPU 221's half");
        compact.CompactInstructions.Should().BeNull();
    }

    [Fact]
    public void Generate_Stats_CountsTheProgramsInstructionsAndNetworks()
    {
        var result = HandlerGenerator.Generate(new HandlerOptions { Protocol = 2, Cpu = CpuProfiles.For(CpuModel.Cpu224), Station = 2 });

        var size = result.Stats!.Size;
        size.Instructions.Should().Be(result.Program!.InstructionCount).And.Be(result.Stats.Instructions);
        size.Networks.Should().Be(result.Program.Blocks.Sum(b => b.Networks.Length));
        size.Networks.Should().Be(CountNetworks(result.AwlText));
        size.Cpu.Should().Be(CpuProfiles.For(CpuModel.Cpu224));
    }

    /// <summary>"Network n" lines in the .awl text, counted independently of the model.</summary>
    private static int CountNetworks(string awl) =>
        awl.Split("\r\n").Count(l => l.StartsWith("Network ", StringComparison.Ordinal));
}
