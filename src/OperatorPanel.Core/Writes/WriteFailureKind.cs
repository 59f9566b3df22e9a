namespace OperatorPanel.Core.Writes;

/// <summary>Why a write was not written. A write the PLC may have applied is never Failed: see <see cref="WriteOutcome.Unknown"/>.</summary>
public enum WriteFailureKind
{
    /// <summary>Refused before sending: the area is not written by the panel, or the address is not on the station's CPU.</summary>
    InvalidRequest,

    /// <summary>The station answered with an error (not writable, address out of range…); nothing was written.</summary>
    RefusedByPlc,

    /// <summary>The request never left the PC: the port could not be opened.</summary>
    LinkFailure,

    /// <summary>A reply came that does not answer a write.</summary>
    UnexpectedReply,

    /// <summary>Polling stopped before the write was sent; nothing was written.</summary>
    EngineStopped,

    /// <summary>Its intent could not be put on record (the write journal unwritable): a write off the record is not sent.</summary>
    NotRecorded,
}
