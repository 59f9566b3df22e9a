namespace OperatorPanel.Simulator.Stl;

/// <summary>What an instruction expects in one operand position; the loader checks and resolves each operand against it.</summary>
internal enum StlOperandType
{
    BitIn,
    BitOut,
    ByteIn,
    ByteOut,
    WordIn,
    WordOut,
    DWordIn,
    DWordOut,

    /// <summary>A byte in memory that a block instruction starts at (BMB, ATH, RCV buffer): no constant.</summary>
    ByteArea,

    /// <summary>A word in memory that BMW starts at: no constant.</summary>
    WordArea,

    /// <summary>A double word in memory that BMD starts at: no constant.</summary>
    DWordArea,

    /// <summary>A label number 0-255 (JMP, LBL).</summary>
    Label,

    /// <summary>A block name (CALL, ATCH).</summary>
    Block,

    /// <summary>An interrupt event number (ATCH, DTCH).</summary>
    Event,

    /// <summary>A port number 0 or 1 (RCV, XMT).</summary>
    Port,

    /// <summary>The timer itself, T0-T255 (TON, TONR, TOF).</summary>
    Timer,

    /// <summary>The counter itself, C0-C255 (CTU, CTD, CTUD).</summary>
    Counter,

    /// <summary>A signed byte (SHRB length N, -64 to +64).</summary>
    SignedByteIn,
}
