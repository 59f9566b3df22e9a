using static OperatorPanel.Stl.Instructions.StlOperands;
using static OperatorPanel.Stl.Instructions.StlStatusBits;
using Group = OperatorPanel.Stl.Instructions.StlInstructionGroup;

namespace OperatorPanel.Stl.Instructions;

public static partial class StlInstructionTable
{
    private const string IndirectAndRange = "SM4.3 (run-time), 0006 (indirect address)";
    private const string BlockErrors = "SM4.3 (run-time), 0006 (indirect address), 0091 (operand out of range)";

    private static IEnumerable<StlInstructionSpec> Moves()
    {
        yield return Entry("MOVB", Group.Move, StlSources.Move, ByteIn("IN"), ByteOut("OUT")) with { EnoErrors = IndirectAndRange };
        yield return Entry("MOVW", Group.Move, StlSources.Move, WordIn("IN", StlDataType.Word), WordOut("OUT", StlDataType.Word)) with { EnoErrors = IndirectAndRange };
        var movdIn = DWordIn("IN", StlDataType.DWord) with { Kinds = DWordInKinds | StlOperandKinds.AddressOf };
        yield return Entry("MOVD", Group.Move, StlSources.Move, movdIn, DWordOut("OUT", StlDataType.DWord)) with { EnoErrors = IndirectAndRange };
        yield return Entry("MOVR", Group.Move, StlSources.Move, RealIn("IN"), RealOut("OUT")) with { EnoErrors = IndirectAndRange };
        yield return Entry("BMB", Group.Move, StlSources.BlockMove,
            ByteArea("IN", StlAccess.Read).Widened(StlExtent.Count), ByteArea("OUT", StlAccess.Write).Widened(StlExtent.Count), Count()) with
        { EnoErrors = BlockErrors };
        var wordIn = new StlOperandSpec("IN", StlDataType.Word, WordMemory | StlOperandKinds.AI, StlAccess.Read).Widened(StlExtent.Count);
        var wordOut = new StlOperandSpec("OUT", StlDataType.Word, WordMemory | StlOperandKinds.AQ, StlAccess.Write).Widened(StlExtent.Count);
        yield return Entry("BMW", Group.Move, StlSources.BlockMove, wordIn, wordOut, Count()) with { EnoErrors = BlockErrors };
        yield return Entry("BMD", Group.Move, StlSources.BlockMove,
            new StlOperandSpec("IN", StlDataType.DWord, DWordMemory, StlAccess.Read).Widened(StlExtent.Count),
            new StlOperandSpec("OUT", StlDataType.DWord, DWordMemory, StlAccess.Write).Widened(StlExtent.Count), Count()) with
        { EnoErrors = BlockErrors };
        yield return Entry("SWAP", Group.Move, StlSources.Swap, WordInOut("IN", StlDataType.Word)) with { EnoErrors = IndirectAndRange };
        var inputByte = new StlOperandSpec("IN", StlDataType.Byte, StlOperandKinds.I | Indirect, StlAccess.Read);
        yield return Entry("BIR", Group.Move, StlSources.ImmediateMove, inputByte, ByteOut("OUT")) with { EnoErrors = IndirectAndRange };
        var outputByte = new StlOperandSpec("OUT", StlDataType.Byte, StlOperandKinds.Q, StlAccess.Write);
        yield return Entry("BIW", Group.Move, StlSources.ImmediateMove, ByteIn("IN"), outputByte) with { EnoErrors = IndirectAndRange };
    }

    private static IEnumerable<StlInstructionSpec> Maths()
    {
        const string overflow = "SM1.1 (overflow), SM4.3 (run-time), 0006 (indirect address)";
        const string divide = "SM1.1 (overflow), SM1.3 (divide by 0), SM4.3 (run-time), 0006 (indirect address)";
        foreach (var (op, bits, eno) in ((string, StlStatusBits, string)[])[("+", Zero | Overflow | Negative, overflow), ("-", Zero | Overflow | Negative, overflow), ("*", Zero | Overflow | Negative, overflow), ("/", Zero | Overflow | Negative | DivideByZero, divide)])
        {
            yield return Entry(op + "I", Group.IntegerMath, StlSources.IntegerMath, WordIn("IN1"), WordInOut("OUT")) with { StatusBits = bits, EnoErrors = eno };
            yield return Entry(op + "D", Group.IntegerMath, StlSources.IntegerMath, DWordIn("IN1"), DWordInOut("OUT")) with { StatusBits = bits, EnoErrors = eno };
            yield return Entry(op + "R", Group.RealMath, StlSources.RealMath, RealIn("IN1"), RealInOut("OUT")) with { StatusBits = bits, EnoErrors = eno };
        }

        yield return Entry("MUL", Group.IntegerMath, StlSources.IntegerMath, WordIn("IN1"), DWordInOut("OUT")) with { StatusBits = Zero | Overflow | Negative, EnoErrors = overflow };
        yield return Entry("DIV", Group.IntegerMath, StlSources.IntegerMath, WordIn("IN1"), DWordInOut("OUT")) with { StatusBits = Zero | Overflow | Negative | DivideByZero, EnoErrors = divide };
        foreach (var function in (string[])["SQRT", "LN", "EXP", "SIN", "COS", "TAN"])
        {
            yield return Entry(function, Group.RealMath, StlSources.RealFunctions, RealIn("IN"), RealOut("OUT")) with { StatusBits = Zero | Overflow | Negative, EnoErrors = overflow };
        }

        yield return Entry("INCB", Group.IntegerMath, StlSources.Increment, ByteInOut("OUT")) with { StatusBits = Zero | Overflow, EnoErrors = overflow };
        yield return Entry("DECB", Group.IntegerMath, StlSources.Increment, ByteInOut("OUT")) with { StatusBits = Zero | Overflow, EnoErrors = overflow };
        yield return Entry("INCW", Group.IntegerMath, StlSources.Increment, WordInOut("OUT")) with { StatusBits = Zero | Overflow | Negative, EnoErrors = overflow };
        yield return Entry("DECW", Group.IntegerMath, StlSources.Increment, WordInOut("OUT")) with { StatusBits = Zero | Overflow | Negative, EnoErrors = overflow };
        yield return Entry("INCD", Group.IntegerMath, StlSources.Increment, DWordInOut("OUT")) with { StatusBits = Zero | Overflow | Negative, EnoErrors = overflow };
        yield return Entry("DECD", Group.IntegerMath, StlSources.Increment, DWordInOut("OUT")) with { StatusBits = Zero | Overflow | Negative, EnoErrors = overflow };
        yield return Entry("PID", Group.Pid, StlSources.Pid, new StlOperandSpec("TBL", StlDataType.Byte, StlOperandKinds.V, StlAccess.ReadWrite).Covering(80),
            Number("LOOP", StlDataType.Byte, 0, 7)) with
        { StatusBits = Overflow, EnoErrors = "SM1.1 (overflow), SM4.3 (run-time), 0006 (indirect address)" };
    }

    private static IEnumerable<StlInstructionSpec> Logic()
    {
        foreach (var op in (string[])["AND", "OR", "XOR"])
        {
            yield return Entry(op + "B", Group.Logic, StlSources.Logic, ByteIn("IN1"), ByteInOut("OUT")) with { StatusBits = Zero, EnoErrors = IndirectAndRange };
            yield return Entry(op + "W", Group.Logic, StlSources.Logic, WordIn("IN1", StlDataType.Word), WordInOut("OUT", StlDataType.Word)) with { StatusBits = Zero, EnoErrors = IndirectAndRange };
            yield return Entry(op + "D", Group.Logic, StlSources.Logic, DWordIn("IN1", StlDataType.DWord), DWordInOut("OUT", StlDataType.DWord)) with { StatusBits = Zero, EnoErrors = IndirectAndRange };
        }

        yield return Entry("INVB", Group.Logic, StlSources.Invert, ByteInOut("OUT")) with { StatusBits = Zero, EnoErrors = IndirectAndRange };
        yield return Entry("INVW", Group.Logic, StlSources.Invert, WordInOut("OUT", StlDataType.Word)) with { StatusBits = Zero, EnoErrors = IndirectAndRange };
        yield return Entry("INVD", Group.Logic, StlSources.Invert, DWordInOut("OUT", StlDataType.DWord)) with { StatusBits = Zero, EnoErrors = IndirectAndRange };
    }

    private static IEnumerable<StlInstructionSpec> ShiftsAndRotates()
    {
        foreach (var op in (string[])["SL", "SR", "RL", "RR"])
        {
            var source = op[0] == 'S' ? StlSources.Shift : StlSources.Rotate;
            yield return Entry(op + "B", Group.ShiftRotate, source, ByteInOut("OUT"), ByteIn("N")) with { StatusBits = Zero | Overflow, EnoErrors = IndirectAndRange };
            yield return Entry(op + "W", Group.ShiftRotate, source, WordInOut("OUT", StlDataType.Word), ByteIn("N")) with { StatusBits = Zero | Overflow, EnoErrors = IndirectAndRange };
            yield return Entry(op + "D", Group.ShiftRotate, source, DWordInOut("OUT", StlDataType.DWord), ByteIn("N")) with { StatusBits = Zero | Overflow, EnoErrors = IndirectAndRange };
        }

        // N of SHRB is signed: -64 to 64, a negative N shifts towards the lower bits.
        var length = new StlOperandSpec("N", StlDataType.Byte, ByteInKinds, StlAccess.Read).Range(-64, 64);
        yield return Entry("SHRB", Group.ShiftRotate, StlSources.ShiftRegister, BitIn("DATA"), BitOut("S_BIT") with { Access = StlAccess.ReadWrite, Extent = StlExtent.AbsoluteCount }, length) with
        {
            StatusBits = Overflow,
            EnoErrors = "SM4.3 (run-time), 0006 (indirect address), 0091 (operand out of range), 0092 (error in count field)",
        };
    }
}
