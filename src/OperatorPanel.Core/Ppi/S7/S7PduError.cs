namespace OperatorPanel.Core.Ppi.S7;

/// <summary>Why a PDU is not the answer (or the job) expected.</summary>
public enum S7PduError
{
    None,

    /// <summary>Shorter than its header, or than its header says.</summary>
    TooShort,

    /// <summary>Byte 0 is not the protocol id 16#32.</summary>
    NotS7,

    /// <summary>A job where an answer belongs, or the other way round, or user data.</summary>
    WrongMessageType,

    /// <summary>Parameter and data lengths in the header do not add up to the PDU's length.</summary>
    LengthMismatch,

    /// <summary>The answer is for another function than the job.</summary>
    WrongFunction,

    /// <summary>The answer has another number of items than the job.</summary>
    ItemCountMismatch,

    /// <summary>An item is cut short, has an unknown size byte, or does not match the item asked.</summary>
    BadItem,

    /// <summary>The header's error class and code are not zero: the CPU refused the whole job.</summary>
    Refused,

    /// <summary>The answer carries another PDU reference than the job (a late answer to an older job).</summary>
    ReferenceMismatch,

    /// <summary>A job with a function this CPU model does not serve.</summary>
    UnknownFunction,
}
