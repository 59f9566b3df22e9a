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
    /// The station runs an Operator Panel handler of an older protocol (v1 or v2): IDENTIFY v3 got no answer but the
    /// station answered a v2 or v1 IDENTIFY (Link/V3/HandlerBeforeV3), or its IDENTIFY reply is not v3's. It ignores the
    /// panel's frames and must be regenerated (opanel generate) and downloaded.
    /// </summary>
    HandlerOutdated,

    /// <summary>
    /// PPI: another master is on the bus (its token frames or its requests were seen). The panel is a PPI master that
    /// never takes part in token passing, so it stops instead of fighting for the bus (docs/ppi.md section 4).
    /// </summary>
    AnotherMaster,
}
