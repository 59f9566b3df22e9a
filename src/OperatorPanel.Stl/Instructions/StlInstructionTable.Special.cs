using static OperatorPanel.Stl.Instructions.StlOperands;
using static OperatorPanel.Stl.Instructions.StlStatusBits;
using Group = OperatorPanel.Stl.Instructions.StlInstructionGroup;
using Kinds = OperatorPanel.Stl.Instructions.StlOperandKinds;

namespace OperatorPanel.Stl.Instructions;

public static partial class StlInstructionTable
{
    private static IEnumerable<StlInstructionSpec> TimersAndCounters()
    {
        var timer = new StlOperandSpec("Txxx", StlDataType.Timer, Kinds.T, StlAccess.ReadWrite).Range(0, 255);
        foreach (var mnemonic in (string[])["TON", "TONR", "TOF"])
        {
            yield return Entry(mnemonic, Group.Timer, StlSources.Timer, timer, WordIn("PT"));
        }

        yield return Entry("BITIM", Group.Timer, StlSources.IntervalTimer, DWordOut("OUT", StlDataType.DWord)) with { Firmware = StlFirmware.Version2 };
        yield return Entry("CITIM", Group.Timer, StlSources.IntervalTimer, DWordIn("IN", StlDataType.DWord), DWordOut("OUT", StlDataType.DWord)) with { Firmware = StlFirmware.Version2 };
        var counter = new StlOperandSpec("Cxxx", StlDataType.Counter, Kinds.C, StlAccess.ReadWrite).Range(0, 255);
        foreach (var mnemonic in (string[])["CTU", "CTD", "CTUD"])
        {
            yield return Entry(mnemonic, Group.Counter, StlSources.Counter, counter, WordIn("PV"));
        }
    }

    private static IEnumerable<StlInstructionSpec> Tables()
    {
        var table = new StlOperandSpec("TBL", StlDataType.Word, WordMemory, StlAccess.ReadWrite);
        const string eno = "SM4.3 (run-time), 0006 (indirect address), 0091 (operand out of range)";
        yield return Entry("ATT", Group.Table, StlSources.Table, WordIn("DATA"), table) with { StatusBits = TableFull, EnoErrors = "SM1.4 (table overflow), " + eno };
        yield return Entry("FIFO", Group.Table, StlSources.Table, table, WordOut("DATA")) with { StatusBits = TableEmpty, EnoErrors = "SM1.5 (empty table), " + eno };
        yield return Entry("LIFO", Group.Table, StlSources.Table, table, WordOut("DATA")) with { StatusBits = TableEmpty, EnoErrors = "SM1.5 (empty table), " + eno };
        foreach (var relation in (string[])["=", "<>", "<", ">"])
        {
            yield return Entry("FND" + relation, Group.Table, StlSources.TableFind, table with { Access = StlAccess.Read }, WordIn("PTN"), WordInOut("INDX")) with { EnoErrors = eno };
        }

        var fillOut = new StlOperandSpec("OUT", StlDataType.Word, WordMemory | Kinds.AQ, StlAccess.Write).Widened(StlExtent.Count);
        yield return Entry("FILL", Group.Table, StlSources.Fill, WordIn("IN"), fillOut, Count()) with { EnoErrors = eno };
    }

    private static IEnumerable<StlInstructionSpec> Clock()
    {
        const string eno = "SM4.3 (run-time), 0006 (indirect address), 000C (clock cartridge not present)";
        yield return Entry("TODR", Group.Clock, StlSources.Clock, ByteArea("T", StlAccess.Write).Covering(8)) with { EnoErrors = eno };
        yield return Entry("TODW", Group.Clock, StlSources.Clock, ByteArea("T", StlAccess.Read).Covering(8)) with { EnoErrors = eno + ", 0007 (TOD data error)" };
        yield return Entry("TODRX", Group.Clock, StlSources.ClockExtended, ByteArea("T", StlAccess.Write).Covering(19)) with { Firmware = StlFirmware.Version2, EnoErrors = eno };
        yield return Entry("TODWX", Group.Clock, StlSources.ClockExtended, ByteArea("T", StlAccess.Read).Covering(19)) with { Firmware = StlFirmware.Version2, EnoErrors = eno + ", 0007 (TOD data error)" };
    }

    private static IEnumerable<StlInstructionSpec> Strings()
    {
        const string eno = "SM4.3 (run-time), 0006 (indirect address), 0091 (operand out of range)";
        var v2 = StlFirmware.Version2;
        yield return Entry("SLEN", Group.String, StlSources.Strings, StringIn("IN"), ByteOut("OUT")) with { Firmware = v2, EnoErrors = eno };
        yield return Entry("SCPY", Group.String, StlSources.Strings, StringIn("IN"), StringArea("OUT", StlAccess.Write)) with { Firmware = v2, EnoErrors = eno };
        yield return Entry("SCAT", Group.String, StlSources.Strings, StringIn("IN"), StringArea("OUT", StlAccess.ReadWrite)) with { Firmware = v2, EnoErrors = eno };
        yield return Entry("SSCPY", Group.String, StlSources.Strings, StringArea("IN", StlAccess.Read), ByteIn("INDX"), ByteIn("N"), StringArea("OUT", StlAccess.Write)) with { Firmware = v2, EnoErrors = eno + ", 009B (index = 0)" };
        var position = new StlOperandSpec("OUT", StlDataType.Byte, ByteOutKinds, StlAccess.ReadWrite);
        yield return Entry("SFND", Group.String, StlSources.Strings, StringArea("IN1", StlAccess.Read), StringArea("IN2", StlAccess.Read), position) with { Firmware = v2, EnoErrors = eno + ", 009B (index = 0)" };
        yield return Entry("CFND", Group.String, StlSources.Strings, StringArea("IN1", StlAccess.Read), StringArea("IN2", StlAccess.Read), position) with { Firmware = v2, EnoErrors = eno + ", 009B (index = 0)" };
    }

    private static IEnumerable<StlInstructionSpec> HighSpeed()
    {
        yield return Entry("HDEF", Group.HighSpeed, StlSources.HighSpeedCounter, Number("HSC", StlDataType.Byte, 0, 5), Number("MODE", StlDataType.Byte, 0, 11)) with
        {
            Placement = StlPlacement.Main | StlPlacement.Subroutine,
            EnoErrors = "SM4.3 (run-time), 0003 (input point conflict), 0004 (illegal instruction in interrupt), 000A (HSC redefinition)",
        };
        yield return Entry("HSC", Group.HighSpeed, StlSources.HighSpeedCounter, Number("N", StlDataType.Word, 0, 5)) with { EnoErrors = "SM4.3 (run-time), 0001 (HSC before HDEF), 0005 (simultaneous HSC/PLS)" };
        yield return Entry("PLS", Group.HighSpeed, StlSources.PulseOutput, Number("N", StlDataType.Word, 0, 1)) with { EnoErrors = "SM4.3 (run-time), 0005 (simultaneous HSC/PLS), 0006 (indirect address)" };
    }
}
