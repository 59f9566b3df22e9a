namespace OperatorPanel.Stl.Instructions;

/// <summary>
/// Where each group of entries comes from; docs/stl-instructions.md, "Sources", resolves the abbreviations. C233 is the
/// System Manual C79000-G7076-C233-01 (pages as printed); MWHELP is STEP 7-Micro/WIN's online help, one page per
/// instruction with its "Inputs/Outputs, Operands, Data Types" table. "unsourced" marks a group whose page was not found.
/// </summary>
internal static class StlSources
{
    public const string Contacts = "MWHELP s7-24lx4.htm";

    public const string ImmediateContacts = "unsourced";

    public const string LogicStack = "C233 p. 9-194; ML1312858 p. 83; SMART p. 174 (AENO)";

    public const string Coils = "unsourced";

    public const string ImmediateCoils = "unsourced";

    public const string Nop = "unsourced";

    public const string Compare = "C233 p. 9-10; CMP Table 6-15";

    public const string StringCompare = "CMP Table 6-15 (Compare String)";

    public const string Move = "unsourced";

    public const string BlockMove = "unsourced";

    public const string Swap = "unsourced";

    public const string ImmediateMove = "unsourced";

    public const string IntegerMath = "MWHELP s7-28hir.htm; C233 p. 9-76; ML801761 p. 154";

    public const string RealMath = "ML801761 p. 154";

    public const string RealFunctions = "unsourced";

    public const string Increment = "unsourced";

    public const string Pid = "unsourced";

    public const string Logic = "unsourced";

    public const string Invert = "unsourced";

    public const string Shift = "C233 p. 9-116; ML801761 p. 193";

    public const string Rotate = "ML801761 p. 193";

    public const string ShiftRegister = "SMART p. 318 (sibling product)";

    public const string Conversion = "DE-SH p. 102 (DTR, DTI, ITD)";

    public const string Bcd = "DE-SH p. 102";

    public const string Decode = "C233 p. 9-131";

    public const string Segment = "unsourced";

    public const string AsciiHex = "C233 p. 9-135; MWHELP s7-26m26.htm";

    public const string NumberToAscii = "unsourced";

    public const string StringConversion = "unsourced";

    public const string Timer = "C233 p. 9-16; ML801761 p. 211";

    public const string IntervalTimer = "unsourced";

    public const string Counter = "C233 p. 9-24; MWHELP s7-27o4z.htm";

    public const string Table = "C233 p. 9-109 (LIFO)";

    public const string TableFind = "unsourced";

    public const string Fill = "unsourced";

    public const string Clock = "A5E02 p. 9-72";

    public const string ClockExtended = "SMART p. 168 (sibling product)";

    public const string Strings = "unsourced";

    public const string HighSpeedCounter = "unsourced";

    public const string PulseOutput = "unsourced";

    public const string End = "MWHELP s7-250fn.htm, s7-29khe.htm";

    public const string Stop = "A5E02 p. 9-146 and MWHELP s7-27sz5.htm (WDR pages: STOP in an interrupt routine)";

    public const string Watchdog = "MWHELP s7-27sz5.htm; A5E02 p. 9-146";

    public const string Jump = "unsourced";

    public const string ForNext = "unsourced";

    public const string Scr = "unsourced";

    public const string DiagnosticLed = "unsourced";

    public const string Subroutine = "MWHELP s7-250fn.htm (RET)";

    public const string Call = "unsourced";

    public const string InterruptEnable = "SMART p. 326 (sibling product); C235 p. 5-15";

    public const string InterruptReturn = "MWHELP s7-250fn.htm (RETI)";

    public const string Attach = "C233 p. 9-165; MWHELP s7-245wz.htm; A5E02 (ML1303220 p. 357); ML801761 p. 172";

    public const string ClearEvent = "unsourced";

    public const string Freeport = "ML801761 p. 101; MWHELP s7-27fw0.htm (TBL through *VD, *AC, *LD)";

    public const string Network = "unsourced";

    public const string PortAddress = "unsourced";
}
