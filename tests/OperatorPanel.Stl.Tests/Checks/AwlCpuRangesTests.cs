using OperatorPanel.Core.Cpu;
using OperatorPanel.Stl.Checks;

namespace OperatorPanel.Stl.Tests.Checks;

/// <summary>The per-CPU memory checks of <see cref="AwlProgramCheck"/> (<see cref="AwlCpuRanges"/>), which the merge and stl run share.</summary>
public sealed class AwlCpuRangesTests
{
    private static System.Collections.Immutable.ImmutableArray<AwlDiagnostic> Check(string instruction, CpuModel model)
    {
        var text = $"ORGANIZATION_BLOCK MAIN:OB1\r\nTITLE=t\r\nBEGIN\r\nNetwork 1\r\nLD     SM0.0\r\n{instruction}\r\nEND_ORGANIZATION_BLOCK\r\n";
        var parsed = AwlParser.Parse(text);
        parsed.Diagnostics.Should().BeEmpty();
        return AwlProgramCheck.Check(parsed.Program, CpuProfiles.For(model));
    }

    [Theory]
    [InlineData("MOVW   1, VW5000", CpuModel.Cpu221, AwlCheckIds.OutOfRange, "'VW5000' is outside the CPU's ranges: VW5000 ends at VB5001, past the last V byte VB2047")]
    [InlineData("MOVB   1, SMB200", CpuModel.Cpu221, AwlCheckIds.OutOfRange, "'SMB200' is outside the CPU's ranges: SMB200 is past the last")]
    [InlineData("MOVW   0, AQW0", CpuModel.Cpu221, AwlCheckIds.OutOfRange, "'AQW0' is outside the CPU's ranges: AQW0: CPU 221 has no analog outputs (AQW)")]
    [InlineData("=      Q20.0", CpuModel.Cpu224, AwlCheckIds.OutOfRange, "'Q20.0' is outside the CPU's ranges: Q20.0 is past the last")]
    [InlineData("MOVD   &VB5000, AC1", CpuModel.Cpu221, AwlCheckIds.OutOfRange, "'&VB5000' is outside the CPU's ranges")]
    [InlineData("MOVB   *VD5000, VB0", CpuModel.Cpu221, AwlCheckIds.OutOfRange, "'*VD5000' is outside the CPU's ranges")]
    [InlineData("MOVB   1, SMB10", CpuModel.Cpu224, AwlCheckIds.OperandKind, "'SMB10' is read-only (SMB0-SMB29, AIW)")]
    public void Check_OperandNotOnTheCpu_IsRefusedAtItsLine(string instruction, CpuModel model, string id, string reason)
    {
        var found = Check(instruction, model);

        found.Should().ContainSingle().Which.Should().Match<AwlDiagnostic>(d => d.Id == id && d.Line == 6 && d.Message.Contains(reason));
    }

    [Theory]
    [InlineData("MOVW   1, VW2046", CpuModel.Cpu221)]
    [InlineData("MOVB   1, SMB179", CpuModel.Cpu221)]
    [InlineData("MOVW   0, AQW0", CpuModel.Cpu224)]
    [InlineData("=      Q15.7", CpuModel.Cpu224)]
    [InlineData("MOVB   SMB10, VB0", CpuModel.Cpu224)]
    [InlineData("MOVB   1, SMB30", CpuModel.Cpu224)]
    public void Check_OperandOnTheCpu_IsNotRefused(string instruction, CpuModel model)
    {
        Check(instruction, model).Should().BeEmpty();
    }
}
