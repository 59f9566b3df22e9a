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

    /// <summary>Body under 8 characters: not even station, sequence, command and block check.</summary>
    TooShort,

    /// <summary>Odd number of body characters: not whole hex pairs.</summary>
    OddLength,

    /// <summary>A body character outside 0-9 and uppercase A-F.</summary>
    NotHex,

    /// <summary>The block check in the last two characters differs from the XOR of the others.</summary>
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
}
