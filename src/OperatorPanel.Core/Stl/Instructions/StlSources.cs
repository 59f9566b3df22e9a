namespace OperatorPanel.Core.Stl.Instructions;

/// <summary>
/// Where each group of entries comes from; docs/stl-instructions.md, "Sources", resolves the abbreviations. C233 is the
/// System Manual C79000-G7076-C233-01 (pages as printed); MWHELP is STEP 7-Micro/WIN's online help, one page per
/// instruction with its "Inputs/Outputs, Operands, Data Types" table. "unsourced" marks a group whose page was not found.
/// </summary>
internal static class StlSources
{
    public const string Contacts = "MWHELP s7-24lx4.htm";

    public const string ImmediateContacts = "unsourced";

    public const string LogicStack = "unsourced";

    public const string Coils = "unsourced";

    public const string ImmediateCoils = "unsourced";

    public const string Nop = "unsourced";

    public const string Compare = "unsourced";

    public const string StringCompare = "unsourced";

    public const string Move = "unsourced";

    public const string BlockMove = "unsourced";

    public const string Swap = "unsourced";

    public const string ImmediateMove = "unsourced";

    public const string IntegerMath = "unsourced";

    public const string RealMath = "unsourced";

    public const string RealFunctions = "unsourced";

    public const string Increment = "unsourced";

    public const string Pid = "unsourced";

    public const string Logic = "unsourced";

    public const string Invert = "unsourced";

    public const string Shift = "C233 p. 9-116";

    public const string Rotate = "unsourced";

    public const string ShiftRegister = "unsourced";

    public const string Conversion = "unsourced";

    public const string Bcd = "unsourced";

    public const string Decode = "unsourced";

    public const string Segment = "unsourced";

    public const string AsciiHex = "C233 p. 9-135; MWHELP s7-26m26.htm";

    public const string NumberToAscii = "unsourced";

    public const string StringConversion = "unsourced";

    public const string Timer = "unsourced";

    public const string IntervalTimer = "unsourced";

    public const string Counter = "unsourced";

    public const string Table = "unsourced";

    public const string TableFind = "unsourced";

    public const string Fill = "unsourced";

    public const string Clock = "unsourced";

    public const string ClockExtended = "unsourced";

    public const string Strings = "unsourced";

    public const string HighSpeedCounter = "unsourced";

    public const string PulseOutput = "unsourced";

    public const string End = "unsourced";

    public const string Stop = "unsourced";

    public const string Watchdog = "unsourced";

    public const string Jump = "unsourced";

    public const string ForNext = "unsourced";

    public const string Scr = "unsourced";

    public const string DiagnosticLed = "unsourced";

    public const string Subroutine = "unsourced";

    public const string InterruptEnable = "unsourced";

    public const string InterruptReturn = "unsourced";

    public const string Attach = "C233 p. 9-165; MWHELP s7-245wz.htm";

    public const string ClearEvent = "unsourced";

    public const string Freeport = "unsourced";

    public const string Network = "unsourced";

    public const string PortAddress = "unsourced";
}
