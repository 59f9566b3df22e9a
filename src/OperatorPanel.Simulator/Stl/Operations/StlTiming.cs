namespace OperatorPanel.Simulator.Stl.Operations;

/// <summary>
/// Execution times in ns, from the manual where a figure is published, otherwise a conservative figure with its reason
/// (docs/sources/s7200-facts.md section 6 lists them with their sources). Every row of <see cref="StlOperations"/>
/// names one of these; there is no fallback. Sources: [A2] System Manual C79000-G7076-C233-01, Tables
/// (CPU 221/222/224 specifications, seed 002): Boolean 0.37 us, Move Word 34 us, timer/counter 50-64 us, single
/// precision (integer) math 46 us, real math 100-400 us per instruction. [F3] German System Manual 2004/05 (manualslib
/// 170165), Tabelle F-3 p. 458: RCV 80 us, RET 13 us, RETI 23 us; length multipliers printed there run from 0.6 to
/// 16.5 us. [F2] System Manual 08/2008 (French edition manualslib 402127 p. 535, Tableau F-2 notes): +14 us per
/// indirect operand, 1 us without power flow.
/// </summary>
internal static class StlTiming
{
    public static readonly StlExecutionTime BitLogic = new(370, "[A2] Boolean execution speed 0.37 us");

    public static readonly StlExecutionTime MoveWord = new(34_000, "[A2] Move Word execution speed 34 us");

    public static readonly StlExecutionTime MoveByte = new(34_000, "no source: MOVW's 34 us [A2], the same instruction family");

    public static readonly StlExecutionTime IntegerMath = new(46_000, "[A2] single precision (integer) math execution speed 46 us");

    /// <summary>The published range is 50-64 us per instruction with no per-instruction figure; the high end is taken.</summary>
    public static readonly StlExecutionTime TimerCounter = new(64_000, "[A2] timer/counter execution speed 50-64 us: the high end");

    public static readonly StlExecutionTime RealMath = new(400_000, "[A2] real math execution speed 100-400 us: the high end");

    public static readonly StlExecutionTime WideIntegerMath = new(100_000, "no source: a 32-bit or dividing integer instruction taken as slow as the low end of real math [A2]");

    public static readonly StlExecutionTime Receive = new(80_000, "[F3] p. 458: RCV 80 us");

    public static readonly StlExecutionTime SystemCall = new(80_000, "no source: RCV's 80 us [F3], like RCV a call into the operating system");

    public static readonly StlExecutionTime Return = new(13_000, "[F3] p. 458: RET 13 us (CRET is its conditional form)");

    public static readonly StlExecutionTime InterruptReturn = new(23_000, "[F3] p. 458: RETI 23 us (CRETI is its conditional form)");

    public static readonly StlExecutionTime EndOfMain = new(13_000, "no source: RET's 13 us [F3], END and MEND end a block as RET does");

    public static readonly StlExecutionTime NoWork = new(370, "no source: does no work; one Boolean instruction [A2]");

    /// <summary>LBL: the interpreter has charged nothing for a label since it began; figures stay comparable.</summary>
    public static readonly StlExecutionTime Label = new(0, "no source: a jump target, resolved when the program loads; charged nothing");

    public static readonly StlExecutionTime Other = new(46_000, "no source: the slowest published figure of a non-real, non-timer instruction ([A2] integer math 46 us)");

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
    public const long InterruptOverhead = 23_000 + 46_000;

    /// <summary>
    /// No source: per byte of BMB/BMW/BMD, per character of ATH/HTA. Conservative: 17 us, the largest length multiplier
    /// printed in [F3] p. 458 (16.5 us) rounded up.
    /// </summary>
    public const long PerByte = 17_000;

    /// <summary>No source: per parameter of a CALL; conservative 46 us, one parameter copy taken as slow as integer math.</summary>
    public const long PerParameter = 46_000;
}
