namespace OperatorPanel.Core.Transport;

/// <summary>What went wrong on the link, for messages, statistics and retry decisions.</summary>
public enum PlcErrorKind
{
    /// <summary>The station did not complete a reply within the reply-time budget.</summary>
    Timeout,

    /// <summary>The port is missing, busy, unplugged or refused by the OS.</summary>
    PortUnavailable,

    /// <summary>Bytes arrived but did not form a valid reply (checksum, hex, length, wrong station or sequence).</summary>
    FrameCorrupt,

    /// <summary>The station answered with an error status.</summary>
    NegativeReply,

    /// <summary>Every retry timed out: the station is off the bus, in STOP, or its mode switch is at TERM.</summary>
    NoAnswer,

    /// <summary>
    /// IDENTIFY got no answer but the station answered the v1 IDENTIFY probe: its handler speaks protocol v1, ignores
    /// every v2 frame, and must be regenerated and downloaded (<see cref="Link.HandlerV1"/>).
    /// </summary>
    HandlerProtocolV1,

    /// <summary>
    /// PPI: another master is on the bus (its token frames or its requests were seen). The panel is a PPI master that
    /// never takes part in token passing, so it stops instead of fighting for the bus (docs/ppi.md section 4).
    /// </summary>
    AnotherMaster,
}
