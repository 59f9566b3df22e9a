using OperatorPanel.Core.Cpu;
using OperatorPanel.StlGen.Diagnostics;
using OperatorPanel.StlGen.Merge;
using OperatorPanel.StlGen.Options;
using OperatorPanel.StlGen.Tests.Merge.UserPrograms;

namespace OperatorPanel.StlGen.Tests.Merge;

/// <summary>The merge refuses the operands <c>opanel stl run --cpu</c> refuses for the project's CPU (one check: Stl AwlCpuRanges).</summary>
public sealed class HandlerMergerCpuRangeTests
{
    private const int Line = UserProgram.FirstInstructionLine;

    private static HandlerOptions For(CpuModel model) => new() { Protocol = 2, Cpu = CpuProfiles.For(model), Station = 2 };

    [Theory]
    [InlineData("MOVW   1, VW5000", CpuModel.Cpu221, "AWL010", "'VW5000' is outside the CPU's ranges")]
    [InlineData("MOVB   1, SMB200", CpuModel.Cpu221, "AWL010", "'SMB200' is outside the CPU's ranges")]
    [InlineData("MOVW   0, AQW0", CpuModel.Cpu221, "AWL010", "AQW0: CPU 221 has no analog outputs (AQW)")]
    [InlineData("=      Q20.0", CpuModel.Cpu224, "AWL010", "'Q20.0' is outside the CPU's ranges")]
    [InlineData("MOVB   1, SMB10", CpuModel.Cpu224, "AWL008", "'SMB10' is read-only")]
    public void Merge_OperandNotOnTheProjectsCpu_IsRefusedAtItsLine(string instruction, CpuModel model, string awlId, string reason)
    {
        var result = HandlerMerger.Merge(UserProgram.Ob1("LD     SM0.0", instruction), For(model));

        result.Ok.Should().BeFalse();
        result.MergedText.Should().BeEmpty();
        var refusal = result.Errors.Should().ContainSingle().Which;
        refusal.Id.Should().Be(StlDiagnostics.UserProgramRefused);
        refusal.Line.Should().Be(Line + 1);
        refusal.Message.Should().Contain($"({awlId})").And.Contain(reason);
    }

    [Fact]
    public void Merge_AnalogOutputOnCpu224_IsMerged()
    {
        var result = HandlerMerger.Merge(UserProgram.Ob1("LD     SM0.0", "MOVW   0, AQW0"), For(CpuModel.Cpu224));

        result.Diagnostics.Should().BeEmpty();
        result.MergedText.Should().Contain("MOVW   0, AQW0");
    }
}
