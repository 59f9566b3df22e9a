using OperatorPanel.StlGen.Diagnostics;
using OperatorPanel.StlGen.Merge;
using OperatorPanel.StlGen.Tests.Merge.UserPrograms;

namespace OperatorPanel.StlGen.Tests.Merge;

/// <summary>CPU 224 handler on port 0 by default: VB7764-VB8191, SBR63, INT125-INT127, events 23, 10, 9.</summary>
public sealed class HandlerMergerCollisionTests
{
    private const int Line = UserProgram.FirstInstructionLine;

    [Theory]
    [InlineData("MOVB   1, VB7764", "VB7764")]
    [InlineData("MOVW   VW7763, VW0", "VW7763 (VB7763-VB7764)")]
    [InlineData("LDD=   VD8188, 0", "VD8188 (VB8188-VB8191)")]
    [InlineData("LD     V8000.3", "V8000.3 (VB8000)")]
    [InlineData("MOVD   &VB8191, AC1", "&VB8191 (VB8191)")]
    [InlineData("BMB    VB0, VB7744, 21", "VB7744 (VB7744-VB7764)")]
    [InlineData("BMW    VW7644, VW0, 61", "VW7644 (VB7644-VB7765)")]
    [InlineData("FILL   0, VW7754, 6", "VW7754 (VB7754-VB7765)")]
    [InlineData("ATH    VB0, VB7763, 4", "VB7763 (VB7763-VB7764)")]
    [InlineData("HTA    VB0, VB7761, 8", "VB7761 (VB7761-VB7768)")]
    [InlineData("S      V7763.7, 2", "V7763.7 (VB7763-VB7764)")]
    [InlineData("SHRB   I0.0, V7763.0, 9", "V7763.0 (VB7763-VB7764)")]
    [InlineData("INCW   VW8190", "VW8190 (VB8190-VB8191)")]
    public void Merge_UserTouchesHandlerVBytes_ReportsOverlapAtItsLine(string instruction, string described)
    {
        var result = HandlerMerger.Merge(UserProgram.Ob1("LD     SM0.0", instruction), UserProgram.Cpu224);

        result.Ok.Should().BeFalse();
        result.MergedText.Should().BeEmpty();
        var overlap = result.Errors.Should().ContainSingle().Which;
        overlap.Id.Should().Be(StlDiagnostics.VMemoryOverlap);
        overlap.Line.Should().Be(Line + 1);
        overlap.Message.Should().StartWith($"{described} overlaps the handler's VB7764-VB8191; move the handler with --buffer VBn");
    }

    [Theory]
    [InlineData("MOVB   1, VB7763")]
    [InlineData("BMB    VB0, VB7744, 20")]
    [InlineData("S      V7763.0, 8")]
    [InlineData("ATH    VB0, VB7763, 2")]
    public void Merge_UserStopsJustBelowHandler_NoCollision(string instruction)
    {
        var result = HandlerMerger.Merge(UserProgram.Ob1("LD     SM0.0", instruction), UserProgram.Cpu224);

        result.Diagnostics.Should().BeEmpty();
        result.MergedText.Should().NotBeEmpty();
    }

    [Fact]
    public void Merge_VOverlap_SuggestsTheHighestFreeBufferStart()
    {
        var result = HandlerMerger.Merge(UserProgram.Ob1("LD     SM0.0", "MOVB   1, VB8000"), UserProgram.Cpu224);

        result.Errors.Single().Message.Should().EndWith("(VB7572-VB7999 is not used by the user's program)");
    }

    [Fact]
    public void Merge_CallParameterInHandlerBuffer_ReportsTheCallLine()
    {
        var sbr = new[] { "SUBROUTINE_BLOCK FILL_IN:SBR0", "VAR_OUTPUT", "RESULT:INT;", "END_VAR", "BEGIN", "Network 1", "LD     SM0.0", "MOVW   1, #RESULT", "END_SUBROUTINE_BLOCK" };
        var result = HandlerMerger.Merge(UserProgram.WithBlocks(["LD     SM0.0", "CALL   FILL_IN, VW8000"], sbr), UserProgram.Cpu224);

        result.Errors.Should().ContainSingle().Which.Should().Match<MergeDiagnostic>(d => d.Id == StlDiagnostics.VMemoryOverlap && d.Line == Line + 1);
    }

    [Theory]
    [InlineData("ATCH   MY_RX, 23", 23)]
    [InlineData("ATCH   MY_TX, 9", 9)]
    [InlineData("ATCH   MY_TICK, 10", 10)]
    [InlineData("DTCH   23", 23)]
    [InlineData("CEVNT  9", 9)]
    [InlineData("CEVNT  23", 23)]
    [InlineData("CEVNT  10", 10)]
    public void Merge_UserUsesHandlerEvent_ReportsEventInUse(string instruction, int number)
    {
        var result = HandlerMerger.Merge(UserProgram.Ob1("LD     SM0.1", instruction), UserProgram.Cpu224);

        var found = result.Errors.Should().ContainSingle().Which;
        found.Should().Match<MergeDiagnostic>(d => d.Id == StlDiagnostics.EventInUse && d.Line == Line + 1);
        found.Message.Should().Contain($"event {number} (");
    }

    [Fact]
    public void Merge_TimedInterruptZeroTaken_AdvisesTimedInterruptOne()
    {
        var result = HandlerMerger.Merge(UserProgram.Ob1("LD     SM0.1", "ATCH   MY_TICK, 10"), UserProgram.Cpu224);

        result.Errors.Single().Message.Should().EndWith("move the user's routine to timed interrupt 1 (event 11, interval SMB35)");
    }

    [Fact]
    public void Merge_UserAttachesOtherPortAndTimedOne_NoCollision()
    {
        // Port 1 and its event 24 exist on the CPU 226 only (a CPU 224 program with them is refused, STL029).
        var result = HandlerMerger.Merge(UserProgram.Ob1("LD     SM0.1", "ATCH   MY_RX, 24", "ATCH   MY_TICK, 11", "RCV    VB100, 1"), UserProgram.Cpu226);

        result.Diagnostics.Should().BeEmpty();
    }

    [Theory]
    [InlineData("CEVNT  11")]
    [InlineData("NETR   VB100, 1")]
    public void Merge_UserClearsOtherEventOrUsesOtherPort_NoCollision(string instruction)
    {
        var result = HandlerMerger.Merge(UserProgram.Ob1("LD     SM0.1", instruction), UserProgram.Cpu226);

        result.Diagnostics.Should().BeEmpty();
    }

    [Fact]
    public void Merge_UserDisablesInterrupts_WarnsAtTheLineAndMerges()
    {
        var result = HandlerMerger.Merge(UserProgram.Ob1("LD     SM0.0", "DISI", "MOVD   VD0, VD4", "ENI"), UserProgram.Cpu224);

        result.Ok.Should().BeTrue();
        result.MergedText.Should().Contain("DISI");
        var warning = result.Warnings.Should().ContainSingle().Which;
        warning.Should().Match<MergeDiagnostic>(d => d.Id == StlDiagnostics.InterruptsDisabled && d.Line == Line + 1);
        warning.Message.Should().StartWith("DISI holds back the handler's interrupts (events 23, 10, 9) until the next ENI");
    }

    [Theory]
    [InlineData("RCV    VB100, 0")]
    [InlineData("XMT    VB100, 0")]
    [InlineData("NETR   VB100, 0")]
    [InlineData("NETW   VB100, 0")]
    [InlineData("ATCH   MY_CHAR, 8")]
    public void Merge_UserTalksOnHandlerPort_ReportsPortInUse(string instruction)
    {
        var result = HandlerMerger.Merge(UserProgram.Ob1("LD     SM0.1", instruction), UserProgram.Cpu226);

        var found = result.Errors.Should().ContainSingle().Which;
        found.Should().Match<MergeDiagnostic>(d => d.Id == StlDiagnostics.PortInUse && d.Line == Line + 1);
        found.Message.Should().EndWith("put the handler on port 1 with --plc-port 1");
    }

    [Theory]
    [InlineData("MOVB   16#09, SMB30")]
    [InlineData("MOVW   0, SMW85")]
    [InlineData("S      SM30.0, 1")]
    [InlineData("=      SM87.7")]
    [InlineData("MOVB   16#3C, SMB88")]
    [InlineData("MOVW   100, SMW92")]
    [InlineData("MOVB   255, SMB94")]
    [InlineData("ORB    16#80, SMB87")]
    public void Merge_UserWritesPortControl_ReportsPortControlWritten(string instruction)
    {
        var result = HandlerMerger.Merge(UserProgram.Ob1("LD     SM0.1", instruction), UserProgram.Cpu224);

        result.Errors.Should().ContainSingle().Which.Should().Match<MergeDiagnostic>(d => d.Id == StlDiagnostics.PortControlWritten && d.Line == Line + 1);
    }

    [Theory]
    [InlineData("MOVB   SMB30, VB0")]
    [InlineData("LDB=   SMB86, 0")]
    [InlineData("MOVB   16#09, SMB130")]
    [InlineData("MOVB   16#3C, SMB188")]
    public void Merge_UserReadsPortControlOrWritesOtherPort_NoCollision(string instruction)
    {
        var result = HandlerMerger.Merge(UserProgram.Ob1("LD     SM0.1", instruction), UserProgram.Cpu224);

        result.Diagnostics.Should().BeEmpty();
    }

    [Theory]
    [InlineData("MOVB   50, SMB34")]
    [InlineData("MOVW   16#3232, SMW34")]
    [InlineData("INCB   SMB34")]
    public void Merge_UserWritesSmb34_ReportsReplyDelayIntervalWritten(string instruction)
    {
        var result = HandlerMerger.Merge(UserProgram.Ob1("LD     SM0.1", instruction), UserProgram.Cpu224);

        result.Errors.Should().ContainSingle().Which.Should().Match<MergeDiagnostic>(d => d.Id == StlDiagnostics.ReplyDelayIntervalWritten && d.Line == Line + 1);
    }

    [Theory]
    [InlineData("MOVB   50, SMB34")]
    [InlineData("ATCH   MY_TICK, 10")]
    public void Merge_Protocol3Handler_LeavesTimedInterrupt0AndSmb34ToTheUser(string instruction)
    {
        var result = HandlerMerger.Merge(UserProgram.Ob1("LD     SM0.1", instruction), UserProgram.Cpu224 with { Protocol = 3 });

        result.Diagnostics.Should().BeEmpty("a v3 handler has no reply-delay interrupt (docs/protocol.md section 0)");
        result.MergedText.Should().Contain(instruction);
    }

    [Fact]
    public void Merge_BlockNumbersAndNamesInUse_ReportsEachAtItsBlockLine()
    {
        string[] blocks =
        [
            "SUBROUTINE_BLOCK LAST:SBR63", "BEGIN", "END_SUBROUTINE_BLOCK",
            "SUBROUTINE_BLOCK OP_RX:SBR5", "BEGIN", "END_SUBROUTINE_BLOCK",
            "INTERRUPT_BLOCK ALARM:INT126", "BEGIN", "END_INTERRUPT_BLOCK",
        ];
        var result = HandlerMerger.Merge(UserProgram.WithBlocks(["LD     SM0.0"], blocks), UserProgram.Cpu224);

        result.Errors.Select(d => (d.Id, d.Line)).Should().Equal(
            (StlDiagnostics.SubroutineNumberInUse, 6), (StlDiagnostics.BlockNameInUse, 9), (StlDiagnostics.InterruptNumberInUse, 12));
        result.Errors.First().Message.Should().EndWith("move the handler's subroutine with --sbr N (SBR62 is free)");
        result.Errors.Last().Message.Should().EndWith("move them with --int N (INT123-INT125 are free)");
    }

    [Theory]
    [InlineData(3, 127, false)] // protocol 3 takes INT125 (receive) and INT126 (transmit complete) only
    [InlineData(3, 126, true)]
    [InlineData(2, 127, true)] // protocol 2 also its reply-delay routine
    public void Merge_UserInterruptRoutineAboveTheHandlers_CollidesOnlyWithAHandlerThatTakesIt(int protocol, int number, bool collides)
    {
        string[] blocks = [$"INTERRUPT_BLOCK ALARM:INT{number}", "BEGIN", "END_INTERRUPT_BLOCK"];

        var result = HandlerMerger.Merge(UserProgram.WithBlocks(["LD     SM0.0"], blocks), UserProgram.Cpu224 with { Protocol = protocol });

        result.Errors.Any(d => d.Id == StlDiagnostics.InterruptNumberInUse).Should().Be(collides);
    }

    [Fact]
    public void Merge_UserProgramDoesNotParse_ReportsParserMessagesAndWritesNothing()
    {
        var text = UserProgram.Ob1("LD     SM0.0") + "garbage line\r\n";

        var result = HandlerMerger.Merge(text, UserProgram.Cpu224);

        result.MergedText.Should().BeEmpty();
        result.Errors.Should().ContainSingle().Which.Should().Match<MergeDiagnostic>(d => d.Id == StlDiagnostics.UserProgramInvalid && d.Line == 6);
    }

    [Fact]
    public void Merge_NoMainBlock_ReportsUserProgramHasNoMain()
    {
        var result = HandlerMerger.Merge("SUBROUTINE_BLOCK A:SBR0\r\nBEGIN\r\nEND_SUBROUTINE_BLOCK\r\n", UserProgram.Cpu224);

        result.Errors.Single().Id.Should().Be(StlDiagnostics.UserProgramHasNoMain);
    }

    [Fact]
    public void Merge_ImpossibleHandlerSetting_ReportsTheGeneratorDiagnostic()
    {
        var result = HandlerMerger.Merge(UserProgram.Ob1("LD     SM0.0"), UserProgram.Cpu224 with { Port = 1 });

        result.Errors.Single().Should().Match<MergeDiagnostic>(d => d.Id == StlDiagnostics.PortNotOnCpu && d.Line == 0);
    }

    [Theory]
    [InlineData("MOVB   1, *VD0", StlDiagnostics.IndirectAccessUnchecked)]
    [InlineData("MOVW   *AC1, VW0", StlDiagnostics.IndirectAccessUnchecked)]
    [InlineData("MOVB   *LD0, VB0", StlDiagnostics.IndirectAccessUnchecked)]
    [InlineData("BMB    VB0, VB10, VB2", StlDiagnostics.BlockLengthUnchecked)]
    [InlineData("MOVW   LEVEL, VW0", StlDiagnostics.SymbolUnchecked)]
    public void Merge_UncheckableAccess_WarnsAndStillMerges(string instruction, string id)
    {
        var result = HandlerMerger.Merge(UserProgram.Ob1("LD     SM0.0", instruction), UserProgram.Cpu224);

        result.Ok.Should().BeTrue();
        result.MergedText.Should().NotBeEmpty();
        result.Warnings.Should().Contain(d => d.Id == id && d.Line == Line + 1);
    }

    [Fact]
    public void Merge_CodePageCharactersInNamesAndComments_AreKeptAsTheyAre()
    {
        string[] subroutine = ["SUBROUTINE_BLOCK Z\u00e4hler:SBR0", "TITLE=Z\u00e4hlt die Flaschen", "BEGIN", "Network 1 // F\u00fcllstand", "LD     SM0.0", "INCW   VW0", "END_SUBROUTINE_BLOCK"];

        var result = HandlerMerger.Merge(UserProgram.WithBlocks(["LD     SM0.0 // F\u00fcllstand \u00b0C", "CALL   Z\u00e4hler"], subroutine), UserProgram.Cpu224);

        result.Diagnostics.Should().BeEmpty();
        result.MergedText.Should().Contain("LD     SM0.0 // F\u00fcllstand \u00b0C\r\nCALL   Z\u00e4hler\r\n")
            .And.Contain("SUBROUTINE_BLOCK Z\u00e4hler:SBR0\r\nTITLE=Z\u00e4hlt die Flaschen\r\n");
    }

    [Fact]
    public void Merge_TwoPortCpu_UserPortZeroIsFineWhenHandlerOnPortOne()
    {
        var result = HandlerMerger.Merge(UserProgram.Ob1("LD     SM0.1", "MOVB   16#09, SMB30", "ATCH   MY_RX, 23", "RCV    VB100, 0"), UserProgram.Cpu226 with { Port = 1 });

        result.Diagnostics.Should().BeEmpty();
    }

    [Theory]
    [InlineData("SHLW   VW0, 1", "(AWL001): SHLW is not an S7-200 STL instruction")]
    [InlineData("LDW==  VW0, 1", "(AWL003): LDW==")]
    [InlineData("ATCH   INT0, 26", "(AWL006): ATCH: the CPU 224 has no interrupt event 26")]
    [InlineData("MEND", "(AWL002): MEND is not written in STL")]
    public void Merge_UserProgramMicroWinRefuses_IsRefusedAtItsLine(string instruction, string reason)
    {
        var result = HandlerMerger.Merge(UserProgram.Ob1("LD     SM0.0", instruction), UserProgram.Cpu224);

        result.MergedText.Should().BeEmpty();
        result.Errors.Should().ContainSingle().Which.Should().Match<MergeDiagnostic>(
            d => d.Id == StlDiagnostics.UserProgramRefused && d.Line == Line + 1 && d.Message.Contains(reason));
    }
}
