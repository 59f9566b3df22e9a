namespace OperatorPanel.Core.Writes;

/// <summary>Why a write was not confirmed. Only <see cref="LinkFailure"/> and <see cref="EngineStopped"/> leave it unknown whether the PLC applied it.</summary>
public enum WriteFailureKind
{
    /// <summary>Refused before sending: the area is not written by the panel, or the address is not on the station's CPU.</summary>
    InvalidRequest,

    /// <summary>The station answered with an error (not writable, address out of range…); nothing was written.</summary>
    RefusedByPlc,

    /// <summary>No valid reply after the link's retries; the PLC may or may not have applied the write.</summary>
    LinkFailure,

    /// <summary>A reply came that does not answer a write.</summary>
    UnexpectedReply,

    /// <summary>Polling stopped before the write was sent (nothing written) or while it was on the wire (unknown).</summary>
    EngineStopped,
}
