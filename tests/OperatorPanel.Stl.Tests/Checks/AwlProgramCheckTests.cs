using OperatorPanel.Core.Cpu;
using OperatorPanel.Stl;
using OperatorPanel.Stl.Checks;

namespace OperatorPanel.Stl.Tests.Checks;

public sealed class AwlProgramCheckTests
{
    private static readonly CpuProfile Cpu224 = CpuProfiles.For(CpuModel.Cpu224);

    /// <summary>OB1 holds <paramref name="main"/> from line 5; SBR0 (INT0 for <paramref name="inInterrupt"/>) holds <paramref name="routine"/>.</summary>
    private static System.Collections.Immutable.ImmutableArray<AwlDiagnostic> Check(string main, string routine = "", CpuProfile? cpu = null, bool inInterrupt = false)
    {
        var kind = inInterrupt ? "INTERRUPT_BLOCK INT_0:INT0" : "SUBROUTINE_BLOCK SBR_0:SBR0";
        var text = $"ORGANIZATION_BLOCK MAIN:OB1\r\nTITLE=t\r\nBEGIN\r\nNetwork 1\r\n{main.Replace("\n", "\r\n", StringComparison.Ordinal)}\r\nEND_ORGANIZATION_BLOCK\r\n"
            + $"{kind}\r\nTITLE=t\r\nVAR_INPUT\r\nn:INT;\r\nEND_VAR\r\nBEGIN\r\nNetwork 1\r\n{routine}\r\nEND_{(inInterrupt ? "INTERRUPT" : "SUBROUTINE")}_BLOCK\r\n";
        var parsed = AwlParser.Parse(text);
        parsed.Diagnostics.Should().BeEmpty();
        return AwlProgramCheck.Check(parsed.Program, cpu ?? Cpu224);
    }

    [Theory]
    [InlineData("SHLW   VW0, 1", AwlCheckIds.UnknownInstruction, "SHLW is not an S7-200 STL instruction")]
    [InlineData("MEND", AwlCheckIds.ImplicitBlockEnd, "Micro/WIN ends every block itself")]
    [InlineData("LDW==  VW0, 5", AwlCheckIds.CompareRelation, "'==' is not an STL compare relation")]
    [InlineData("LD     SM0.0\nS      Q0.0, 0", AwlCheckIds.CountIsZero, "N = 0")]
    [InlineData("MOVW   VB0, VW2", AwlCheckIds.OperandKind, "'VB0' is a byte; IN is a WORD")]
    [InlineData("MOVW   VW0, 5", AwlCheckIds.OperandKind, "a constant cannot be OUT")]
    [InlineData("MOVW   AQW0, VW2", AwlCheckIds.OperandKind, "'AQW0' (an analog output) cannot be IN")]
    [InlineData("LDI    M0.0", AwlCheckIds.OperandKind, "cannot be bit")]
    [InlineData("MOVB   VB0", AwlCheckIds.OperandCount, "MOVB takes 2 operand(s) (IN, OUT), found 1")]
    [InlineData("JMP    256", AwlCheckIds.OutOfRange, "outside n's range 0-255")]
    [InlineData("ATCH   INT0, 24", AwlCheckIds.EventNotOnCpu, "the CPU 224 has no interrupt event 24")]
    [InlineData("XMT    VB0, 1", AwlCheckIds.OutOfRange, "the CPU 224 has no port 1")]
    [InlineData("CRET", AwlCheckIds.WrongBlockKind, "CRET can only be used in a subroutine")]
    [InlineData("LDS    9", AwlCheckIds.OutOfRange, "outside N's range 1-8")]
    [InlineData("TON    T256, 10", AwlCheckIds.OutOfRange, "'T256' is outside Txxx's range 0-255")]
    public void Check_WhatMicroWinRefuses_IsRefusedWithIdAndLine(string main, string id, string reason)
    {
        var found = Check(main);

        found.Should().ContainSingle().Which.Should().Match<AwlDiagnostic>(d => d.Id == id && d.Line >= 5 && d.Message.Contains(reason));
    }

    [Theory]
    [InlineData("RET")]
    [InlineData("RETI")]
    public void Check_ExplicitReturn_IsRefusedInEveryBlock(string mnemonic)
    {
        Check("LD     SM0.0", mnemonic).Should().ContainSingle().Which.Id.Should().Be(AwlCheckIds.ImplicitBlockEnd);
        Check("LD     SM0.0", mnemonic, inInterrupt: true).Should().ContainSingle().Which.Id.Should().Be(AwlCheckIds.ImplicitBlockEnd);
    }

    [Theory]
    [InlineData("ENI")]
    [InlineData("DISI")]
    [InlineData("HDEF   0, 1")]
    [InlineData("END")]
    public void Check_InstructionForbiddenInInterruptRoutines_IsRefusedThere(string instruction)
    {
        var found = Check("LD     SM0.0", instruction, inInterrupt: true);

        found.Should().ContainSingle().Which.Should().Match<AwlDiagnostic>(d => d.Id == (instruction == "END" ? AwlCheckIds.WrongBlockKind : AwlCheckIds.NotInInterruptRoutine) && d.Line == 14);
    }

    [Theory]
    [InlineData(CpuModel.Cpu221, 13, false)]
    [InlineData(CpuModel.Cpu222, 19, true)]
    [InlineData(CpuModel.Cpu222, 26, false)]
    [InlineData(CpuModel.Cpu224, 23, true)]
    [InlineData(CpuModel.Cpu224, 25, false)]
    [InlineData(CpuModel.Cpu224, 27, true)]
    [InlineData(CpuModel.Cpu224XP, 26, true)]
    [InlineData(CpuModel.Cpu226, 33, true)]
    [InlineData(CpuModel.Cpu226, 34, false)]
    public void Check_AttachEvent_IsCheckedAgainstTheCpusEvents(CpuModel model, int eventNumber, bool accepted)
    {
        var found = Check($"ATCH   INT0, {eventNumber}", cpu: CpuProfiles.For(model));

        found.Select(d => d.Id).Should().Equal(accepted ? [] : [eventNumber > 33 ? AwlCheckIds.OutOfRange : AwlCheckIds.EventNotOnCpu]);
    }

    [Fact]
    public void Check_WhatRealExportsContain_IsAccepted()
    {
        const string main = """
            LD     SM0.0
            CALL   SBR0, VW10
            CALL   SBR_0, 5
            ATCH   INT0, 10
            LD     I0.0
            TON    T37, 50
            LD     T37
            A      C1
            O      T38
            =      Q0.0
            LDW>=  C1, 50
            R      T37, 1
            MOVW   T37, VW0
            MOVB   'A', VB2
            MOVW   'AB', VW4
            AENO
            LDS    1
            CTU    C1, 5
            LDR<   VD0, 1.5
            MOVD   &VB100, AC1
            MOVW   *AC1, VW6
            SLW    VW0, 4
            SHRB   I0.3, V100.0, +4
            SHRB   I0.3, V100.0, -4
            NOP    0
            END
            """;

        Check(main, "LD     SM0.0\nMOVW   #n, VW8\nCRET").Should().BeEmpty();
    }

    [Fact]
    public void Check_FirmwareTwoInstructionOnEarlyCpu_IsRefused()
    {
        var early = CpuProfiles.For(CpuModel.Cpu224, CpuRevision.Early);

        Check("LD     SM0.0\nTODRX  VB0", cpu: early).Should().ContainSingle().Which.Id.Should().Be(AwlCheckIds.NeedsFirmware2);
        Check("LD     SM0.0\nTODRX  VB0").Should().BeEmpty();
    }

    [Fact]
    public void Check_LocalOfWrongType_IsRefused()
    {
        Check("LD     SM0.0", "LD     SM0.0\nMOVB   #n, VB0").Should().ContainSingle().Which.Message.Should().Contain("'#n' is declared INT; IN is a BYTE");
    }
}
