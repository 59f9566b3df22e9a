using static OperatorPanel.Stl.Instructions.StlOperands;
using Group = OperatorPanel.Stl.Instructions.StlInstructionGroup;
using Kinds = OperatorPanel.Stl.Instructions.StlOperandKinds;

namespace OperatorPanel.Stl.Instructions;

public static partial class StlInstructionTable
{
    private static IEnumerable<StlInstructionSpec> ProgramControl()
    {
        var label = Number("n", StlDataType.Label, 0, 255);
        yield return Entry("END", Group.ProgramControl, StlSources.End) with { Placement = StlPlacement.Main };
        yield return Entry("MEND", Group.ProgramControl, StlSources.End) with { Placement = StlPlacement.None };
        yield return Entry("STOP", Group.ProgramControl, StlSources.Stop);
        yield return Entry("WDR", Group.ProgramControl, StlSources.Watchdog);
        yield return Entry("JMP", Group.ProgramControl, StlSources.Jump, label);
        yield return Entry("LBL", Group.ProgramControl, StlSources.Jump, label);
        yield return Entry("FOR", Group.ProgramControl, StlSources.ForNext, WordInOut("INDX"), WordIn("INIT"), WordIn("FINAL"));
        yield return Entry("NEXT", Group.ProgramControl, StlSources.ForNext);
        var segment = new StlOperandSpec("S_bit", StlDataType.Bool, Kinds.S, StlAccess.ReadWrite);
        yield return Entry("LSCR", Group.ProgramControl, StlSources.Scr, segment with { Access = StlAccess.Read });
        yield return Entry("SCRT", Group.ProgramControl, StlSources.Scr, segment);
        yield return Entry("SCRE", Group.ProgramControl, StlSources.Scr);
        yield return Entry("CSCRE", Group.ProgramControl, StlSources.Scr);
        yield return Entry("DLED", Group.ProgramControl, StlSources.DiagnosticLed, ByteIn("IN")) with { Firmware = StlFirmware.Version2 };
        var subroutine = new StlOperandSpec("SBR_n", StlDataType.Subroutine, Kinds.Pou, StlAccess.Read);
        yield return Entry("CALL", Group.Subroutine, StlSources.Call, subroutine) with { TakesParameters = true, EnoErrors = "SM4.3 (run-time), 0008 (maximum subroutine nesting exceeded)" };
        yield return Entry("CRET", Group.Subroutine, StlSources.Call) with { Placement = StlPlacement.Subroutine };
        yield return Entry("RET", Group.Subroutine, StlSources.Subroutine) with { Placement = StlPlacement.None };
    }

    private static IEnumerable<StlInstructionSpec> Interrupts()
    {
        var routine = new StlOperandSpec("INT", StlDataType.InterruptRoutine, Kinds.Pou, StlAccess.Read);
        var outsideInterrupts = StlPlacement.Main | StlPlacement.Subroutine;
        yield return Entry("ENI", Group.Interrupt, StlSources.InterruptEnable) with { Placement = outsideInterrupts };
        yield return Entry("DISI", Group.Interrupt, StlSources.InterruptEnable) with { Placement = outsideInterrupts };
        yield return Entry("CRETI", Group.Interrupt, StlSources.InterruptReturn) with { Placement = StlPlacement.InterruptRoutine };
        yield return Entry("RETI", Group.Interrupt, StlSources.InterruptReturn) with { Placement = StlPlacement.None };
        yield return Entry("ATCH", Group.Interrupt, StlSources.Attach, routine, Number("EVNT", StlDataType.Event, 0, 33)) with { EnoErrors = "SM4.3 (run-time), 0002 (conflicting assignment of inputs to an HSC)" };
        yield return Entry("DTCH", Group.Interrupt, StlSources.Attach, Number("EVNT", StlDataType.Event, 0, 33)) with { EnoErrors = "SM4.3 (run-time)" };
        yield return Entry("CEVNT", Group.Interrupt, StlSources.ClearEvent, Number("EVNT", StlDataType.Event, 0, 33)) with { Firmware = StlFirmware.Version2, EnoErrors = "SM4.3 (run-time)" };
    }

    private static IEnumerable<StlInstructionSpec> Communication()
    {
        var buffer = new StlOperandSpec("TBL", StlDataType.Byte, Kinds.I | Kinds.Q | Kinds.V | Kinds.M | Kinds.SM | Kinds.S | Indirect, StlAccess.Read).Covering(256);
        var port = Number("PORT", StlDataType.Port, 0, 1);
        const string freeport = "SM4.3 (run-time), 0006 (indirect address), 0009 (simultaneous XMT/RCV on port 0), 000B (simultaneous XMT/RCV on port 1), 000E (RCV parameter error)";
        yield return Entry("XMT", Group.Communication, StlSources.Freeport, buffer, port) with { EnoErrors = freeport };
        yield return Entry("RCV", Group.Communication, StlSources.Freeport, buffer with { Access = StlAccess.Write }, port) with { EnoErrors = freeport };
        var network = new StlOperandSpec("TBL", StlDataType.Byte, Kinds.V | Kinds.M | Indirect, StlAccess.ReadWrite).Covering(23);
        const string ppi = "SM4.3 (run-time), 0006 (indirect address), 0091 (operand out of range), 0092 (error in count field)";
        yield return Entry("NETR", Group.Communication, StlSources.Network, network, port) with { EnoErrors = ppi };
        yield return Entry("NETW", Group.Communication, StlSources.Network, network, port) with { EnoErrors = ppi };
        yield return Entry("GPA", Group.Communication, StlSources.PortAddress, ByteOut("ADDR"), port) with { EnoErrors = IndirectAndRange };
        yield return Entry("SPA", Group.Communication, StlSources.PortAddress, ByteIn("ADDR"), port) with { EnoErrors = IndirectAndRange + ", 0091 (operand out of range)" };
    }
}
