using System.Collections.Frozen;

namespace OperatorPanel.Simulator.Stl;

/// <summary>
/// Execution times in ns, from the manual where a figure is published, otherwise the high end of the published
/// figures of the same kind (docs/sources/s7200-facts.md section 6 lists every row with its source). Sources:
/// [A2] System Manual C79000-G7076-C233-01, Tables A-2 to A-4 (CPU 221/222/224 specifications, seed 002): Boolean
/// 0.37 us, Move Word 34 us, single precision (integer) math 46 us, timer/counter 50-64 us, real math 100-400 us per
/// instruction. [F3] German System Manual 2004/05 (manualslib 170165), Tabelle F-3 p. 458: RCV 80 us, RET 13 us,
/// RETI 23 us; length multipliers printed there run from 0.6 to 16.5 us. [F2] System Manual 08/2008 (French edition
/// manualslib 402127 p. 535, Tableau F-2 notes): +14 us per indirect operand, 1 us without power flow.
/// </summary>
internal static class StlTiming
{
    private const long Boolean = 370;
    private const long MoveWord = 34_000;
    private const long IntegerMath = 46_000;
    private const long Receive = 80_000;

    /// <summary>[F2]: each indirectly addressed operand adds 14 us.</summary>
    public const long IndirectOperand = 14_000;

    /// <summary>[F2]: a box instruction without power flow takes 1 us.</summary>
    public const long WithoutPowerFlow = 1_000;

    /// <summary>No source: housekeeping of one scan (self-test, communication, I/O update) besides OB1; an estimate.</summary>
    public const long ScanOverhead = 250_000;

    /// <summary>
    /// Entering and leaving an interrupt routine: RETI 23 us [F3] plus the entry, which has no source (conservative:
    /// 46 us, the slowest published non-real, non-timer instruction).
    /// </summary>
    public const long InterruptOverhead = 23_000 + IntegerMath;

    /// <summary>
    /// No source: per byte of BMB/BMW, per character of ATH/HTA. Conservative: 17 us, the largest length multiplier
    /// printed in [F3] p. 458 (16.5 us) rounded up.
    /// </summary>
    public const long PerByte = 17_000;

    /// <summary>No source: per parameter of a CALL; conservative 46 us, one parameter copy taken as slow as integer math.</summary>
    public const long PerParameter = IntegerMath;

    /// <summary>
    /// No source: an opcode not in the table (the interpreter gains opcodes over time). Conservative: 400 us, the
    /// slowest published per-instruction figure (real math, [A2]).
    /// </summary>
    public const long Unlisted = 400_000;

    private static readonly FrozenDictionary<StlOpCode, long> Figures = new Dictionary<StlOpCode, long>
    {
        // [A2] Boolean execution speed 0.37 us per instruction: contacts, coils and the logic stack.
        [StlOpCode.Ld] = Boolean,
        [StlOpCode.Ldn] = Boolean,
        [StlOpCode.A] = Boolean,
        [StlOpCode.An] = Boolean,
        [StlOpCode.O] = Boolean,
        [StlOpCode.On] = Boolean,
        [StlOpCode.Not] = Boolean,
        [StlOpCode.Lps] = Boolean,
        [StlOpCode.Lrd] = Boolean,
        [StlOpCode.Lpp] = Boolean,
        [StlOpCode.Ald] = Boolean,
        [StlOpCode.Old] = Boolean,
        [StlOpCode.Assign] = Boolean,

        // No source: a jump target and NOP do no work; conservative = one Boolean instruction.
        [StlOpCode.Lbl] = Boolean,
        [StlOpCode.Nop] = Boolean,

        // [A2] Move Word 34 us; MOVB taken equal (no source, same instruction family).
        [StlOpCode.MovW] = MoveWord,
        [StlOpCode.MovB] = MoveWord,

        // [A2] single precision (integer) math 46 us.
        [StlOpCode.AddI] = IntegerMath,
        [StlOpCode.SubI] = IntegerMath,
        [StlOpCode.AddD] = IntegerMath,
        [StlOpCode.SubD] = IntegerMath,
        [StlOpCode.MulI] = IntegerMath,

        // No source: multiplications and divisions of double words; conservative 100 us, the low end of real math [A2].
        [StlOpCode.MulD] = 100_000,
        [StlOpCode.DivI] = 100_000,
        [StlOpCode.DivD] = 100_000,

        // [F3] p. 458.
        [StlOpCode.Rcv] = Receive,
        [StlOpCode.Ret] = 13_000,
        [StlOpCode.Cret] = 13_000,
        [StlOpCode.Reti] = 23_000,
        [StlOpCode.Creti] = 23_000,

        // No source: XMT and the interrupt set-up instructions call into the operating system like RCV; RCV's 80 us.
        [StlOpCode.Xmt] = Receive,
        [StlOpCode.Atch] = Receive,
        [StlOpCode.Dtch] = Receive,
        [StlOpCode.Eni] = Receive,
        [StlOpCode.Disi] = Receive,

        // No source: END/MEND end a block like RET; RET's 13 us.
        [StlOpCode.End] = 13_000,
        [StlOpCode.Mend] = 13_000,
    }.ToFrozenDictionary();

    /// <summary>
    /// The base time of one instruction with power flow. No source for the rest of the word, double-word, logic,
    /// conversion, compare, shift, block, ASCII and loop instructions: conservative 46 us, the slowest published
    /// non-real, non-timer figure [A2] (block and ASCII instructions add <see cref="PerByte"/>).
    /// </summary>
    public static long Base(StlOpCode code) =>
        Figures.TryGetValue(code, out var figure) ? figure : IsIntegerKind(code) ? IntegerMath : Unlisted;

    private static bool IsIntegerKind(StlOpCode code) => code is StlOpCode.Eu or StlOpCode.Ed or StlOpCode.Set or StlOpCode.Reset
        or StlOpCode.CmpLd or StlOpCode.CmpA or StlOpCode.CmpO or StlOpCode.MovD or StlOpCode.Bmb or StlOpCode.Bmw
        or StlOpCode.Swap or StlOpCode.IncB or StlOpCode.IncW or StlOpCode.IncD or StlOpCode.DecB or StlOpCode.DecW
        or StlOpCode.DecD or StlOpCode.Bti or StlOpCode.Itb or StlOpCode.Itd or StlOpCode.Dti or StlOpCode.AndB
        or StlOpCode.OrB or StlOpCode.XorB or StlOpCode.InvB or StlOpCode.AndW or StlOpCode.OrW or StlOpCode.XorW
        or StlOpCode.InvW or StlOpCode.AndD or StlOpCode.OrD or StlOpCode.XorD or StlOpCode.InvD or StlOpCode.Slb
        or StlOpCode.Srb or StlOpCode.Slw or StlOpCode.Srw or StlOpCode.Sld or StlOpCode.Srd or StlOpCode.Ath
        or StlOpCode.Hta or StlOpCode.For or StlOpCode.Next or StlOpCode.Jmp or StlOpCode.Call;
}
