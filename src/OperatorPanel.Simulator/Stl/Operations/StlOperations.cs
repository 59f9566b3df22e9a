using System.Collections.Frozen;
using System.Collections.Immutable;
using System.Diagnostics.CodeAnalysis;
using static OperatorPanel.Simulator.Stl.Operations.StlOpCode;
using static OperatorPanel.Simulator.Stl.Operations.StlTiming;
using Bits = OperatorPanel.Simulator.Stl.Operations.BitLogicInstructions;
using Compares = OperatorPanel.Simulator.Stl.Operations.CompareInstructions;
using Control = OperatorPanel.Simulator.Stl.Operations.ProgramControlInstructions;
using Convert = OperatorPanel.Simulator.Stl.Operations.ConversionInstructions;
using IntMath = OperatorPanel.Simulator.Stl.Operations.IntegerMathInstructions;
using Logical = OperatorPanel.Simulator.Stl.Operations.LogicalInstructions;
using Moves = OperatorPanel.Simulator.Stl.Operations.MoveInstructions;
using Reals = OperatorPanel.Simulator.Stl.Operations.RealMathInstructions;
using Shifts = OperatorPanel.Simulator.Stl.Operations.ShiftRotateInstructions;

namespace OperatorPanel.Simulator.Stl.Operations;

// Over 150 lines: one row per instruction the simulator executes reads best as one table; the handlers are in the
// *Instructions classes of this folder.

/// <summary>
/// The simulator's instruction table: for every STL mnemonic it executes, the op code the loader links by, the
/// execution time (<see cref="StlTiming"/>, each figure with its source) and the handler. The operands each takes come
/// from the Stl project's <c>StlInstructionTable</c> (docs/stl-instructions.md); a mnemonic of that table that is not
/// here is in <see cref="NotExecuted"/> with the reason, and the loader refuses it by name and line. A test holds the
/// two tables together.
/// </summary>
internal static class StlOperations
{
    private static readonly FrozenDictionary<string, StlOperation> ByMnemonic =
        Rows().ToFrozenDictionary(r => r.Mnemonic, StringComparer.Ordinal);

    /// <summary>Every row, in the order of the manual's instruction groups.</summary>
    public static ImmutableArray<StlOperation> All { get; } = [.. Rows()];

    /// <summary>Instructions of the manual the simulator does not execute, each with the reason the loader gives.</summary>
    public static FrozenDictionary<string, string> NotExecuted { get; } = Refused().ToFrozenDictionary(StringComparer.Ordinal);

    public static bool TryGet(string mnemonic, [NotNullWhen(true)] out StlOperation? operation) =>
        ByMnemonic.TryGetValue(mnemonic, out operation);

    private static IEnumerable<StlOperation> Rows()
    {
        yield return Any("LD", Ld, BitLogic, Bits.Load);
        yield return Any("LDN", Ldn, BitLogic, Bits.LoadNot);
        yield return Any("A", A, BitLogic, Bits.And);
        yield return Any("AN", An, BitLogic, Bits.AndNot);
        yield return Any("O", O, BitLogic, Bits.Or);
        yield return Any("ON", On, BitLogic, Bits.OrNot);
        yield return Any("NOT", Not, BitLogic, Bits.Not);
        yield return Any("EU", Eu, Other, Bits.RisingEdge);
        yield return Any("ED", Ed, Other, Bits.FallingEdge);
        yield return Any("LPS", Lps, BitLogic, Bits.LogicPush);
        yield return Any("LRD", Lrd, BitLogic, Bits.LogicRead);
        yield return Any("LPP", Lpp, BitLogic, Bits.LogicPop);
        yield return Any("ALD", Ald, BitLogic, Bits.AndLoad);
        yield return Any("OLD", Old, BitLogic, Bits.OrLoad);
        yield return Any("LDS", Lds, BitLogic, Bits.LoadStack);
        yield return Any("AENO", Aeno, BitLogic, Bits.AndEno);
        yield return Any("=", Assign, BitLogic, Bits.Assign);
        yield return Box("S", Set, Other, Bits.Set);
        yield return Box("R", Reset, Other, Bits.Reset);
        yield return Any("NOP", Nop, NoWork, Bits.NoOperation);
        yield return Any("LDI", Ldi, Other, Bits.LoadImmediate);
        yield return Any("LDNI", Ldni, Other, Bits.LoadNotImmediate);
        yield return Any("AI", Ai, Other, Bits.AndImmediate);
        yield return Any("ANI", Ani, Other, Bits.AndNotImmediate);
        yield return Any("OI", Oi, Other, Bits.OrImmediate);
        yield return Any("ONI", Oni, Other, Bits.OrNotImmediate);
        yield return Any("=I", AssignI, Other, Bits.AssignImmediate);
        yield return Box("SI", SetI, Other, Bits.SetImmediate);
        yield return Box("RI", ResetI, Other, Bits.ResetImmediate);
        foreach (var row in CompareRows())
        {
            yield return row;
        }

        yield return Box("MOVB", MovB, MoveByte, Moves.Byte);
        yield return Box("MOVW", MovW, MoveWord, Moves.Word);
        yield return Box("MOVD", MovD, Other, Moves.DoubleWord);
        yield return Box("MOVR", MovR, Other, Moves.DoubleWord);
        yield return Box("BMB", Bmb, Other, Moves.BlockOfBytes);
        yield return Box("BMW", Bmw, Other, Moves.BlockOfWords);
        yield return Box("BMD", Bmd, Other, Moves.BlockOfDoubleWords);
        yield return Box("SWAP", Swap, Other, Moves.Swap);
        yield return Box("BIR", Bir, Other, Moves.ReadInputImmediate);
        yield return Box("BIW", Biw, Other, Moves.WriteOutputImmediate);
        yield return Box("+I", AddI, IntegerMath, IntMath.AddInteger);
        yield return Box("-I", SubI, IntegerMath, IntMath.SubtractInteger);
        yield return Box("*I", MulI, IntegerMath, IntMath.MultiplyInteger);
        yield return Box("/I", DivI, WideIntegerMath, IntMath.DivideInteger);
        yield return Box("+D", AddD, IntegerMath, IntMath.AddDouble);
        yield return Box("-D", SubD, IntegerMath, IntMath.SubtractDouble);
        yield return Box("*D", MulD, WideIntegerMath, IntMath.MultiplyDouble);
        yield return Box("/D", DivD, WideIntegerMath, IntMath.DivideDouble);
        yield return Box("MUL", Mul, WideIntegerMath, IntMath.MultiplyToDouble);
        yield return Box("DIV", Div, WideIntegerMath, IntMath.DivideWithRemainder);
        yield return Box("INCB", IncB, Other, IntMath.IncrementByte);
        yield return Box("DECB", DecB, Other, IntMath.DecrementByte);
        yield return Box("INCW", IncW, Other, IntMath.IncrementWord);
        yield return Box("DECW", DecW, Other, IntMath.DecrementWord);
        yield return Box("INCD", IncD, Other, IntMath.IncrementDouble);
        yield return Box("DECD", DecD, Other, IntMath.DecrementDouble);
        yield return Box("+R", AddR, StlTiming.RealMath, Reals.Add);
        yield return Box("-R", SubR, StlTiming.RealMath, Reals.Subtract);
        yield return Box("*R", MulR, StlTiming.RealMath, Reals.Multiply);
        yield return Box("/R", DivR, StlTiming.RealMath, Reals.Divide);
        yield return Box("SQRT", Sqrt, StlTiming.RealMath, Reals.SquareRoot);
        yield return Box("LN", Ln, StlTiming.RealMath, Reals.NaturalLogarithm);
        yield return Box("EXP", Exp, StlTiming.RealMath, Reals.Exponential);
        yield return Box("SIN", Sin, StlTiming.RealMath, Reals.Sine);
        yield return Box("COS", Cos, StlTiming.RealMath, Reals.Cosine);
        yield return Box("TAN", Tan, StlTiming.RealMath, Reals.Tangent);
        yield return Box("ANDB", AndB, Other, Logical.And(1));
        yield return Box("ORB", OrB, Other, Logical.Or(1));
        yield return Box("XORB", XorB, Other, Logical.Xor(1));
        yield return Box("INVB", InvB, Other, Logical.Invert(1));
        yield return Box("ANDW", AndW, Other, Logical.And(2));
        yield return Box("ORW", OrW, Other, Logical.Or(2));
        yield return Box("XORW", XorW, Other, Logical.Xor(2));
        yield return Box("INVW", InvW, Other, Logical.Invert(2));
        yield return Box("ANDD", AndD, Other, Logical.And(4));
        yield return Box("ORD", OrD, Other, Logical.Or(4));
        yield return Box("XORD", XorD, Other, Logical.Xor(4));
        yield return Box("INVD", InvD, Other, Logical.Invert(4));
        yield return Box("SLB", Slb, Other, Shifts.Shift(1, left: true));
        yield return Box("SRB", Srb, Other, Shifts.Shift(1, left: false));
        yield return Box("SLW", Slw, Other, Shifts.Shift(2, left: true));
        yield return Box("SRW", Srw, Other, Shifts.Shift(2, left: false));
        yield return Box("SLD", Sld, Other, Shifts.Shift(4, left: true));
        yield return Box("SRD", Srd, Other, Shifts.Shift(4, left: false));
        yield return Box("RLB", Rlb, Other, Shifts.Rotate(1, left: true));
        yield return Box("RRB", Rrb, Other, Shifts.Rotate(1, left: false));
        yield return Box("RLW", Rlw, Other, Shifts.Rotate(2, left: true));
        yield return Box("RRW", Rrw, Other, Shifts.Rotate(2, left: false));
        yield return Box("RLD", Rld, Other, Shifts.Rotate(4, left: true));
        yield return Box("RRD", Rrd, Other, Shifts.Rotate(4, left: false));
        yield return Box("SHRB", Shrb, Other, Shifts.ShiftRegister);
        yield return Box("BTI", Bti, Other, Convert.ByteToInteger);
        yield return Box("ITB", Itb, Other, Convert.IntegerToByte);
        yield return Box("ITD", Itd, Other, Convert.IntegerToDouble);
        yield return Box("DTI", Dti, Other, Convert.DoubleToInteger);
        yield return Box("DTR", Dtr, StlTiming.RealMath, Convert.DoubleToReal);
        yield return Box("ROUND", Round, StlTiming.RealMath, Convert.Round);
        yield return Box("TRUNC", Trunc, StlTiming.RealMath, Convert.Truncate);
        yield return Box("BCDI", Bcdi, Other, Convert.BcdToInteger);
        yield return Box("IBCD", Ibcd, Other, Convert.IntegerToBcd);
        yield return Box("DECO", Deco, Other, Convert.Decode);
        yield return Box("ENCO", Enco, Other, Convert.Encode);
        yield return Box("SEG", Seg, Other, Convert.Segment);
        yield return Box("ATH", Ath, Other, AsciiInstructions.AsciiToHex);
        yield return Box("HTA", Hta, Other, AsciiInstructions.HexToAscii);
        yield return Box("ITA", Ita, Other, AsciiInstructions.IntegerToAscii);
        yield return Box("DTA", Dta, Other, AsciiInstructions.DoubleToAscii);
        yield return Box("RTA", Rta, StlTiming.RealMath, AsciiInstructions.RealToAscii);
        yield return Any("TON", Ton, TimerCounter, TimerCounterInstructions.Timer);
        yield return Any("TONR", Tonr, TimerCounter, TimerCounterInstructions.Timer);
        yield return Any("TOF", Tof, TimerCounter, TimerCounterInstructions.Timer);
        yield return Any("CTU", Ctu, TimerCounter, TimerCounterInstructions.Counter);
        yield return Any("CTD", Ctd, TimerCounter, TimerCounterInstructions.Counter);
        yield return Any("CTUD", Ctud, TimerCounter, TimerCounterInstructions.Counter);
        yield return Box("ATT", Att, Other, TableInstructions.Add);
        yield return Box("FIFO", Fifo, Other, TableInstructions.First);
        yield return Box("LIFO", Lifo, Other, TableInstructions.Last);
        yield return Box("FND=", Fnd, Other, TableInstructions.Find);
        yield return Box("FND<>", Fnd, Other, TableInstructions.Find);
        yield return Box("FND<", Fnd, Other, TableInstructions.Find);
        yield return Box("FND>", Fnd, Other, TableInstructions.Find);
        yield return Box("FILL", Fill, Other, TableInstructions.Fill);
        yield return Box("FOR", For, Other, Control.For) with { Unpowered = Control.SkipLoop };
        yield return Any("NEXT", Next, Other, Control.Next);
        yield return Box("JMP", Jmp, Other, Control.Jump) with { Unpowered = Control.JumpNotTaken };
        yield return Any("LBL", Lbl, Label, Bits.NoOperation);
        yield return Box("CALL", Call, Other, Control.Call);
        yield return Box("CRET", Cret, StlTiming.Return, Control.Return);
        yield return Any("RET", Ret, StlTiming.Return, Control.Return);
        yield return Box("END", End, EndOfMain, Control.EndMain);
        yield return Any("MEND", Mend, EndOfMain, Control.EndMain);
        yield return Box("STOP", Stop, Other, Control.Stop);
        yield return Box("WDR", Wdr, Other, Control.ResetWatchdog);
        yield return Any("LSCR", Lscr, Other, Control.LoadScr);
        yield return Box("SCRT", Scrt, Other, Control.TransitionScr);
        yield return Any("SCRE", Scre, Other, Control.EndScr);
        yield return Box("CSCRE", Cscre, Other, Control.ConditionalEndScr);
        yield return Box("ATCH", Atch, SystemCall, InterruptInstructions.Attach);
        yield return Box("DTCH", Dtch, SystemCall, InterruptInstructions.Detach);
        yield return Box("ENI", Eni, SystemCall, InterruptInstructions.Enable);
        yield return Box("DISI", Disi, SystemCall, InterruptInstructions.Disable);
        yield return Box("CRETI", Creti, InterruptReturn, Control.Return);
        yield return Any("RETI", Reti, InterruptReturn, Control.Return);
        yield return Box("RCV", Rcv, Receive, InterruptInstructions.Receive);
        yield return Box("XMT", Xmt, SystemCall, InterruptInstructions.Transmit);
        yield return Box("TODR", Todr, Other, ClockInstructions.Read);
        yield return Box("TODW", Todw, Other, ClockInstructions.Write);
        const string highSpeed = "high-speed counters and pulse outputs drive hardware the simulator does not model";
        yield return Box("HDEF", Hdef, Other, Bits.NoOperation) with { NotSimulated = highSpeed };
        yield return Box("HSC", Hsc, Other, Bits.NoOperation) with { NotSimulated = highSpeed };
        yield return Box("PLS", Pls, Other, Bits.NoOperation) with { NotSimulated = highSpeed };
    }

    /// <summary>LDB= ... OR&gt;=: the form (LD, A, O) and width (B, W, D, R) pick the row; the relation goes to op.N.</summary>
    private static IEnumerable<StlOperation> CompareRows()
    {
        foreach (var relation in OperatorPanel.Stl.Instructions.StlInstructionTable.Relations)
        {
            foreach (var width in (string[])["B", "W", "D"])
            {
                yield return Any($"LD{width}{relation}", CmpLd, Other, Compares.Load);
                yield return Any($"A{width}{relation}", CmpA, Other, Compares.And);
                yield return Any($"O{width}{relation}", CmpO, Other, Compares.Or);
            }

            yield return Any($"LDR{relation}", CmpRLd, StlTiming.RealMath, Compares.LoadReal);
            yield return Any($"AR{relation}", CmpRA, StlTiming.RealMath, Compares.AndReal);
            yield return Any($"OR{relation}", CmpRO, StlTiming.RealMath, Compares.OrReal);
        }
    }

    private static IEnumerable<KeyValuePair<string, string>> Refused()
    {
        const string ppi = "the simulator models the Freeport ports only, not a PPI network";
        const string firmware2 = "a CPU firmware 2.0 instruction the simulator does not execute yet";
        foreach (var mnemonic in (string[])["NETR", "NETW", "GPA", "SPA"])
        {
            yield return new(mnemonic, ppi);
        }

        yield return new("PID", "PID loop control is not modelled");
        string[] version2 = ["DLED", "CEVNT", "BITIM", "CITIM", "TODRX", "TODWX", "SLEN", "SCPY", "SCAT", "SSCPY", "SFND", "CFND", "STI", "STD", "STR", "ITS", "DTS", "RTS"];
        foreach (var mnemonic in version2)
        {
            yield return new(mnemonic, firmware2);
        }

        foreach (var form in (string[])["LDS", "AS", "OS"])
        {
            yield return new(form + "=", "string compares are not executed yet");
            yield return new(form + "<>", "string compares are not executed yet");
        }
    }

    private static StlOperation Any(string mnemonic, StlOpCode code, StlExecutionTime time, StlHandler handler) =>
        new(mnemonic, code, time, StlPowerFlow.Any, handler);

    private static StlOperation Box(string mnemonic, StlOpCode code, StlExecutionTime time, StlHandler handler) =>
        new(mnemonic, code, time, StlPowerFlow.Required, handler);
}
