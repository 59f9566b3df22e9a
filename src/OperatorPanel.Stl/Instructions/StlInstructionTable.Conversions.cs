using static OperatorPanel.Stl.Instructions.StlOperands;
using static OperatorPanel.Stl.Instructions.StlStatusBits;
using Group = OperatorPanel.Stl.Instructions.StlInstructionGroup;

namespace OperatorPanel.Stl.Instructions;

public static partial class StlInstructionTable
{
    private static IEnumerable<StlInstructionSpec> Conversions()
    {
        const string eno = IndirectAndRange;
        const string overflow = "SM1.1 (overflow), SM4.3 (run-time), 0006 (indirect address)";
        yield return Entry("BTI", Group.Conversion, StlSources.Conversion, ByteIn("IN"), WordOut("OUT")) with { EnoErrors = eno };
        yield return Entry("ITB", Group.Conversion, StlSources.Conversion, WordIn("IN"), ByteOut("OUT")) with { StatusBits = Overflow, EnoErrors = overflow };
        yield return Entry("ITD", Group.Conversion, StlSources.Conversion, WordIn("IN"), DWordOut("OUT")) with { EnoErrors = eno };
        yield return Entry("DTI", Group.Conversion, StlSources.Conversion, DWordIn("IN"), WordOut("OUT")) with { StatusBits = Overflow, EnoErrors = overflow };
        yield return Entry("DTR", Group.Conversion, StlSources.Conversion, DWordIn("IN"), RealOut("OUT")) with { EnoErrors = eno };
        yield return Entry("ROUND", Group.Conversion, StlSources.Conversion, RealIn("IN"), DWordOut("OUT")) with { StatusBits = Overflow, EnoErrors = overflow };
        yield return Entry("TRUNC", Group.Conversion, StlSources.Conversion, RealIn("IN"), DWordOut("OUT")) with { StatusBits = Overflow, EnoErrors = overflow };
        const string bcd = "SM1.6 (invalid BCD), SM4.3 (run-time), 0006 (indirect address)";
        yield return Entry("BCDI", Group.Conversion, StlSources.Bcd, WordInOut("OUT", StlDataType.Word)) with { StatusBits = BcdError, EnoErrors = bcd };
        yield return Entry("IBCD", Group.Conversion, StlSources.Bcd, WordInOut("OUT", StlDataType.Word)) with { StatusBits = BcdError, EnoErrors = bcd };
        yield return Entry("DECO", Group.Conversion, StlSources.Decode, ByteIn("IN"), WordOut("OUT", StlDataType.Word)) with { EnoErrors = eno };
        yield return Entry("ENCO", Group.Conversion, StlSources.Decode, WordIn("IN", StlDataType.Word), ByteOut("OUT")) with { EnoErrors = eno };
        yield return Entry("SEG", Group.Conversion, StlSources.Segment, ByteIn("IN"), ByteOut("OUT")) with { EnoErrors = eno };
        var hexOut = ByteArea("OUT", StlAccess.Write);
        yield return Entry("ATH", Group.Conversion, StlSources.AsciiHex,
            ByteArea("IN", StlAccess.Read).Widened(StlExtent.Count), hexOut.Widened(StlExtent.HalfCount), ByteIn("LEN")) with
        {
            StatusBits = AsciiError,
            EnoErrors = "SM1.7 (invalid ASCII), SM4.3 (run-time), 0006 (indirect address), 0091 (operand out of range)",
        };
        yield return Entry("HTA", Group.Conversion, StlSources.AsciiHex,
            ByteArea("IN", StlAccess.Read).Widened(StlExtent.HalfCount), hexOut.Widened(StlExtent.Count), ByteIn("LEN")) with
        { EnoErrors = BlockErrors };
        const string format = "SM4.3 (run-time), 0006 (indirect address), illegal format";
        yield return Entry("ITA", Group.Conversion, StlSources.NumberToAscii, WordIn("IN"), ByteArea("OUT", StlAccess.Write), ByteIn("FMT")) with { EnoErrors = format };
        yield return Entry("DTA", Group.Conversion, StlSources.NumberToAscii, DWordIn("IN"), ByteArea("OUT", StlAccess.Write), ByteIn("FMT")) with { EnoErrors = format };
        yield return Entry("RTA", Group.Conversion, StlSources.NumberToAscii, RealIn("IN"), ByteArea("OUT", StlAccess.Write), ByteIn("FMT")) with { EnoErrors = format };
        var index = new StlOperandSpec("INDX", StlDataType.Byte, ByteMemory, StlAccess.ReadWrite);
        const string fromString = "SM1.1 (overflow), SM4.3 (run-time), 0006 (indirect address), 0091 (operand out of range), 009B (index = 0)";
        yield return Entry("STI", Group.Conversion, StlSources.StringConversion, StringIn("IN"), index, WordOut("OUT")) with { Firmware = StlFirmware.Version2, StatusBits = Overflow, EnoErrors = fromString };
        yield return Entry("STD", Group.Conversion, StlSources.StringConversion, StringIn("IN"), index, DWordOut("OUT")) with { Firmware = StlFirmware.Version2, StatusBits = Overflow, EnoErrors = fromString };
        yield return Entry("STR", Group.Conversion, StlSources.StringConversion, StringIn("IN"), index, RealOut("OUT")) with { Firmware = StlFirmware.Version2, StatusBits = Overflow, EnoErrors = fromString };
        const string toString = "SM4.3 (run-time), 0006 (indirect address), 0091 (operand out of range), illegal format";
        yield return Entry("ITS", Group.Conversion, StlSources.StringConversion, WordIn("IN"), StringArea("OUT", StlAccess.Write), ByteIn("FMT")) with { Firmware = StlFirmware.Version2, EnoErrors = toString };
        yield return Entry("DTS", Group.Conversion, StlSources.StringConversion, DWordIn("IN"), StringArea("OUT", StlAccess.Write), ByteIn("FMT")) with { Firmware = StlFirmware.Version2, EnoErrors = toString };
        yield return Entry("RTS", Group.Conversion, StlSources.StringConversion, RealIn("IN"), StringArea("OUT", StlAccess.Write), ByteIn("FMT")) with { Firmware = StlFirmware.Version2, EnoErrors = toString };
    }
}
