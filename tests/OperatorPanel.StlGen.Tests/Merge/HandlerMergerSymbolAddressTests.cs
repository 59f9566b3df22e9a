using OperatorPanel.Simulator.Stl;
using OperatorPanel.StlGen.Diagnostics;
using OperatorPanel.StlGen.Merge;
using OperatorPanel.StlGen.Tests.Merge.UserPrograms;

namespace OperatorPanel.StlGen.Tests.Merge;

/// <summary>NAME:ADDRESS operands as a real export writes them (<c>A P13a_Rot_Des:M2.0</c>): merged, checked as the address.</summary>
public sealed class HandlerMergerSymbolAddressTests
{
    private const int Line = UserProgram.FirstInstructionLine;

    [Fact]
    public void Merge_SymbolWithAddress_IsMergedUnchangedAndRuns()
    {
        var result = HandlerMerger.Merge(UserProgram.Ob1("LD     M1.1", "A      P13a_Rot_Des:M2.0", "=      Q0.0"), UserProgram.Cpu224);

        result.Diagnostics.Should().BeEmpty();
        result.MergedText.Should().Contain("A      P13a_Rot_Des:M2.0\r\n");
        StlProgramLoader.Load(result.MergedText, UserProgram.Cpu224.Cpu).Diagnostics.Should().BeEmpty();
    }

    [Fact]
    public void Merge_SymbolWithAddressInHandlerBytes_ReportsTheOverlapOfTheAddress()
    {
        var result = HandlerMerger.Merge(UserProgram.Ob1("LD     SM0.0", "MOVB   1, Puffer:VB7764"), UserProgram.Cpu224);

        result.Errors.Should().ContainSingle().Which.Should().Match<MergeDiagnostic>(d => d.Id == StlDiagnostics.VMemoryOverlap && d.Line == Line + 1);
    }
}
