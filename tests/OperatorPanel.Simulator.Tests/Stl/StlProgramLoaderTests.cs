using OperatorPanel.Core.Cpu;
using OperatorPanel.Simulator.Stl;

namespace OperatorPanel.Simulator.Tests.Stl;

public sealed class StlProgramLoaderTests
{
    private static StlLoadResult Load(string body, string blocks = "", CpuModel model = CpuModel.Cpu224) =>
        StlProgramLoader.Load(StlTestPrograms.Text(body, blocks), CpuProfiles.For(model));

    [Fact]
    public void Load_UnknownInstruction_ReportsNameAndLineAndGivesNoProgram()
    {
        var result = Load("LD     SM0.0\nPID    VB100, 0");

        result.Succeeded.Should().BeFalse();
        result.Diagnostics.Select(d => d.ToString()).Should().Equal("line 5: PID is not implemented by the simulator: PID loop control is not modelled");
    }

    [Theory]
    [InlineData("MOVB   VB0, VB2048", "VB2048")]
    [InlineData("MOVB   VW0, VB0", "is a word")]
    [InlineData("MOVB   VB0, SMB1", "read-only")]
    [InlineData("MOVB   300, VB0", "outside IN's range 0-255")]
    [InlineData("CALL   NOWHERE", "'NOWHERE' is not the name of a subroutine")]
    [InlineData("ATCH   INT_9, 23", "not the name of an interrupt routine")]
    [InlineData("XMT    VB0, 1", "the CPU 221 has no port 1")]
    [InlineData("JMP    4", "no LBL 4")]
    [InlineData("MOVB   T37, VB0", "'T37' (a timer) cannot be IN")]
    [InlineData("MOVW   T256, VW0", "T0-T255")]
    [InlineData("TON    T0, +10", "TONR timer")]
    [InlineData("TONR   T37, +10", "TON/TOF timer")]
    [InlineData("CTU    T5, +10", "cannot be Cxxx")]
    [InlineData("BIR    VB0, VB1", "cannot be IN (BYTE: IB")]
    [InlineData("=I     M0.0", "(BOOL: Q)")]
    [InlineData("LSCR   M0.0", "(BOOL: S)")]
    [InlineData("SHRB   I0.0, V0.0, 200", "outside N's range -64-64")]
    [InlineData("MOVB   #x, VB0", "not declared")]
    public void Load_BadOperand_IsReportedWithLine(string instruction, string reason)
    {
        var result = Load("LD     SM0.0\n" + instruction, model: CpuModel.Cpu221);

        result.Succeeded.Should().BeFalse();
        result.Diagnostics.Should().ContainSingle().Which.Should().Match<OperatorPanel.Stl.AwlDiagnostic>(d => d.Line == 5 && d.Message.Contains(reason));
    }

    [Fact]
    public void Load_PortOneOnCpu226_IsAccepted()
    {
        Load("LD     SM0.0\nXMT    VB0, 1", model: CpuModel.Cpu226).Succeeded.Should().BeTrue();
    }

    [Fact]
    public void Load_ParseErrors_AreReturnedWithLoadErrors()
    {
        var result = StlProgramLoader.Load("NONSENSE\r\n" + StlTestPrograms.Text("XYZ"), CpuProfiles.For(CpuModel.Cpu224));

        result.Diagnostics.Select(d => d.Line).Should().Equal(1, 5);
    }

    [Fact]
    public void Load_NumericPouReferences_ReachTheNumberedBlocks()
    {
        const string blocks = "SUBROUTINE_BLOCK MY_SUB:SBR3\r\nBEGIN\r\nNetwork 1\r\nLD     SM0.0\r\n=      M0.0\r\nEND_SUBROUTINE_BLOCK\r\n"
            + "INTERRUPT_BLOCK MY_INT:INT2\r\nBEGIN\r\nNetwork 1\r\nLD     SM0.0\r\n=      M0.1\r\nEND_INTERRUPT_BLOCK\r\n";

        var result = Load("LD     SM0.0\nCALL   SBR3\nATCH   INT2, 10\nENI", blocks);

        result.Diagnostics.Should().BeEmpty();
    }

    [Fact]
    public void Run_SubroutineNamedWithCodePageCharacters_IsCalledByThatName()
    {
        const string blocks = "SUBROUTINE_BLOCK Z\u00e4hler:SBR0\r\nBEGIN\r\nNetwork 1 // Z\u00e4hlt\r\nLD     SM0.0\r\nINCW   VW0\r\nEND_SUBROUTINE_BLOCK\r\n";

        var plc = StlTestPrograms.OneScan("LD     SM0.0\nCALL   Z\u00e4hler", blocks);

        plc.Memory.V[1].Should().Be(1, "one scan called the subroutine once (INCW VW0 adds 1 to VB1)");
    }

    [Theory]
    [InlineData(12, "HSC0 CV=PV")]
    [InlineData(19, "PLS0 PTO complete")]
    [InlineData(21, "timer T32 CT=PT")]
    [InlineData(33, "HSC5 CV=PV")]
    public void Load_AttachToAnEventTheSimulatorNeverRaises_WarnsOnceNamingTheEvent(int eventNumber, string name)
    {
        const string routine = "INTERRUPT_BLOCK EDGE:INT0\r\nBEGIN\r\nNetwork 1\r\nLD     SM0.0\r\nINCW   VW0\r\nEND_INTERRUPT_BLOCK\r\n";

        var result = Load($"LD     SM0.1\nATCH   EDGE, {eventNumber}\nATCH   EDGE, {eventNumber}\nENI", routine, CpuModel.Cpu226);

        result.Succeeded.Should().BeTrue("the rest of the program runs");
        result.Warnings.Should().ContainSingle().Which.ToString().Should().Be(
            $"line 5: ATCH: event {eventNumber} ({name}) never fires in the simulator; its routine runs only for the events it can raise (--strict refuses it)");
    }

    [Fact]
    public void Load_AttachToAnEventTheSimulatorNeverRaisesStrict_IsRefused()
    {
        const string routine = "INTERRUPT_BLOCK EDGE:INT0\r\nBEGIN\r\nNetwork 1\r\nLD     SM0.0\r\nINCW   VW0\r\nEND_INTERRUPT_BLOCK\r\n";

        var result = StlProgramLoader.Load(StlTestPrograms.Text("LD     SM0.1\nATCH   EDGE, 12", routine), CpuProfiles.For(CpuModel.Cpu224), new StlLoadOptions { Strict = true });

        result.Succeeded.Should().BeFalse();
        result.Diagnostics.Should().ContainSingle().Which.Message.Should().StartWith("ATCH: event 12 (HSC0 CV=PV) never fires in the simulator");
    }

    [Theory]
    [InlineData(0)]
    [InlineData(7)]
    public void Load_AttachToAnInputEdge_LoadsWithoutWarning(int eventNumber)
    {
        const string routine = "INTERRUPT_BLOCK EDGE:INT0\r\nBEGIN\r\nNetwork 1\r\nLD     SM0.0\r\nINCW   VW0\r\nEND_INTERRUPT_BLOCK\r\n";

        var result = Load($"LD     SM0.1\nATCH   EDGE, {eventNumber}\nENI", routine);

        (result.Succeeded, result.Warnings.Length).Should().Be((true, 0));
    }

    [Theory]
    [InlineData(9)]
    [InlineData(10)]
    [InlineData(26)]
    public void Load_AttachToAnEventTheSimulatorRaises_IsAccepted(int eventNumber)
    {
        const string routine = "INTERRUPT_BLOCK EDGE:INT0\r\nBEGIN\r\nNetwork 1\r\nLD     SM0.0\r\nINCW   VW0\r\nEND_INTERRUPT_BLOCK\r\n";

        var result = Load($"LD     SM0.1\nATCH   EDGE, {eventNumber}\nDTCH   0\nENI", routine, CpuModel.Cpu226);

        result.Diagnostics.Should().BeEmpty();
    }

    [Fact]
    public void Load_WhatMicroWinRefuses_IsReportedOnceWithItsId()
    {
        var result = Load("LD     SM0.0\nSHLW   VW0, 1");

        result.Diagnostics.Should().ContainSingle().Which.ToString().Should().Be("line 5: AWL001 SHLW is not an S7-200 STL instruction (see docs/stl-instructions.md)");
    }

    [Fact]
    public void Load_TableInstructionTheSimulatorDoesNotExecute_IsRefusedByNameAndLine()
    {
        var result = Load("LD     SM0.0\nNETR   VB0, 0");

        result.Diagnostics.Select(d => d.ToString()).Should().Equal(
            "line 5: NETR is not implemented by the simulator: the simulator models the Freeport ports only, not a PPI network");
    }
}
