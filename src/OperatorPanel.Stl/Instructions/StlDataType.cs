namespace OperatorPanel.Stl.Instructions;

/// <summary>
/// The data type column of the manual's operand tables, plus the special operands that are numbers of something:
/// a label, a POU, an interrupt event, a port, a timer or counter.
/// </summary>
public enum StlDataType
{
    Bool,
    Byte,
    Word,
    Int,
    DWord,
    DInt,
    Real,

    /// <summary>A string in memory (a length byte, then the characters), or a string constant.</summary>
    String,

    /// <summary>A label number 0-255 (JMP, LBL).</summary>
    Label,

    /// <summary>A subroutine (CALL).</summary>
    Subroutine,

    /// <summary>An interrupt routine (ATCH).</summary>
    InterruptRoutine,

    /// <summary>An interrupt event number (ATCH, DTCH, CEVNT).</summary>
    Event,

    /// <summary>A communication port 0 or 1 (XMT, RCV, NETR, NETW, GPA, SPA).</summary>
    Port,

    /// <summary>A timer number T0-T255 (TON, TONR, TOF).</summary>
    Timer,

    /// <summary>A counter number C0-C255 (CTU, CTD, CTUD).</summary>
    Counter,
}
