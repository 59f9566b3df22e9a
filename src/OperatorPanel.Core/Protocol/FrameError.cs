namespace OperatorPanel.Core.Protocol;

/// <summary>Why received characters are not a usable frame or not the reply to the request in flight.</summary>
public enum FrameError
{
    None,

    /// <summary>The characters do not begin with '&lt;'.</summary>
    BadStart,

    /// <summary>The characters do not end with '&gt;'.</summary>
    BadEnd,

    /// <summary>More than 255 characters (one RCV buffer) without an end character.</summary>
    TooLong,

    /// <summary>Under 12 characters: not even '&lt;', station, sequence, command, four check characters and '&gt;'.</summary>
    TooShort,

    /// <summary>Odd number of body characters: not whole hex pairs.</summary>
    OddLength,

    /// <summary>A body character outside 0-9 and uppercase A-F.</summary>
    NotHex,

    /// <summary>One of the four characters before '&gt;' lies outside 16#60-16#6F: not a check character.</summary>
    BadCheckCharacter,

    /// <summary>The check in the four check characters differs from the CRC of the body characters.</summary>
    ChecksumMismatch,

    /// <summary>The command byte lacks bit 7: a request (or our own echo), not a reply.</summary>
    NotAReply,

    /// <summary>The reply comes from another station than the one asked.</summary>
    StationMismatch,

    /// <summary>The reply echoes another sequence number: a late reply to an older request.</summary>
    SequenceMismatch,

    /// <summary>The reply answers another command than the one sent.</summary>
    CommandMismatch,

    /// <summary>The reply's payload length does not fit its status and the request.</summary>
    LengthMismatch,

    /// <summary>The reply's status byte is not one the protocol sends.</summary>
    UnknownStatus,

    /// <summary>
    /// STATION, SEQ and CMD match, but the reply's REQCHECK is not the check of the request sent: the PLC acted on a
    /// corrupted copy of it. After a WRITE or WRITE BIT the PLC executed something else (resolve by reading back);
    /// after any other command, retry once. Never a refusal, even when the reply carries an error status.
    /// </summary>
    RequestCheckMismatch,
}
