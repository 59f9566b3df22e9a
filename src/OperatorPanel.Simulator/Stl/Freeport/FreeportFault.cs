namespace OperatorPanel.Simulator.Stl.Freeport;

/// <summary>
/// Why the last RCV or XMT did nothing. On the S7-200 these end the box with ENO = 0 (and the simultaneous case with
/// non-fatal error 0009 for port 0 / 000B for port 1; facts section 8, best knowledge); the port keeps the reason
/// here for the host and the tests, because IStlPort's calls return nothing.
/// </summary>
public enum FreeportFault
{
    None,

    /// <summary>SMB30/SMB130 mm is not 01 (or the CPU left RUN): the port is in PPI and ignores RCV and XMT.</summary>
    NotFreeport,

    /// <summary>XMT while a receive is enabled, or RCV while transmitting (error 0009 / 000B); the call is ignored.</summary>
    SimultaneousTransmitReceive,

    /// <summary>RCV with en = 1 while a receive is already active: ignored, the active receive carries on.</summary>
    ReceiveAlreadyActive,

    /// <summary>XMT while the previous XMT is still sending: ignored.</summary>
    TransmitterBusy,

    /// <summary>RCV set-up without a start condition, il+sc with SMW90 = 0, SMB94 = 0, tmr with SMW92 = 0: SMB86 = r.</summary>
    ReceiveParameterError,

    /// <summary>The buffer (count byte plus characters) does not fit in V memory.</summary>
    BufferOutOfRange,
}
