namespace OperatorPanel.Simulator.Stl;

/// <summary>
/// Nominal execution times in ns. The per-instruction table of the manual is not in our sources
/// (docs/sources/s7200-facts.md section 6), so every figure here is an ESTIMATE in the ranges that section gives:
/// bit logic 0.22 us (newer CPUs, Table 1-1 via EXTRACT), moves and compares a few us, block and ASCII operations a
/// base plus a per-byte multiplier. Confirmed: +14 us for each indirectly addressed operand, and 1 us for a box
/// instruction without power flow (FR402127 Tableau F-2 notes). One table, so a better figure changes one line.
/// </summary>
internal static class StlTiming
{
    /// <summary>Confirmed: each indirectly addressed operand adds 14 us.</summary>
    public const long IndirectOperand = 14_000;

    /// <summary>Confirmed: a box instruction without power flow takes 1 us.</summary>
    public const long WithoutPowerFlow = 1_000;

    /// <summary>Estimate: housekeeping of one scan (self-test, communication, I/O update) besides OB1.</summary>
    public const long ScanOverhead = 250_000;

    /// <summary>Estimate: entering and leaving an interrupt routine.</summary>
    public const long InterruptOverhead = 10_000;

    /// <summary>Estimate: per byte for BMB/BMW, per character for ATH/HTA.</summary>
    public const long PerByte = 600;

    /// <summary>Estimate: per parameter of a CALL.</summary>
    public const long PerParameter = 1_500;

    /// <summary>The base estimate of one instruction with power flow.</summary>
    public static long Base(StlOpCode code) => code switch
    {
        StlOpCode.Ld or StlOpCode.Ldn or StlOpCode.A or StlOpCode.An or StlOpCode.O or StlOpCode.On or StlOpCode.Not
            or StlOpCode.Lps or StlOpCode.Lrd or StlOpCode.Lpp or StlOpCode.Ald or StlOpCode.Old or StlOpCode.Assign => 220,
        StlOpCode.Eu or StlOpCode.Ed => 400,
        StlOpCode.Set or StlOpCode.Reset => 1_000,
        StlOpCode.CmpLd or StlOpCode.CmpA or StlOpCode.CmpO => 1_500,
        StlOpCode.MovB or StlOpCode.MovW or StlOpCode.MovD or StlOpCode.Swap => 1_800,
        StlOpCode.Bmb or StlOpCode.Bmw => 5_000,
        StlOpCode.MulI or StlOpCode.MulD => 6_000,
        StlOpCode.DivI or StlOpCode.DivD => 25_000,
        StlOpCode.Ath or StlOpCode.Hta => 12_000,
        StlOpCode.For => 7_000,
        StlOpCode.Next => 3_000,
        StlOpCode.Jmp or StlOpCode.Cret or StlOpCode.Creti => 1_000,
        StlOpCode.Lbl or StlOpCode.Nop => 0,
        StlOpCode.Call => 8_000,
        StlOpCode.Ret or StlOpCode.Reti or StlOpCode.End or StlOpCode.Mend => 500,
        StlOpCode.Atch or StlOpCode.Dtch => 15_000,
        StlOpCode.Eni or StlOpCode.Disi => 8_000,
        StlOpCode.Rcv or StlOpCode.Xmt => 30_000,
        _ => 2_500,
    };
}
