namespace OperatorPanel.Core.Ppi.S7;

/// <summary>
/// Area codes of an S7 item address as the S7-200 takes them (libnodave nodave.h; HslCommunication SiemensPPI
/// AnalysisAddress; docs/ppi.md section 6 gives each code's sources and confidence).
/// </summary>
public enum S7Area : byte
{
    /// <summary>"System info of 200 family" (libnodave daveSysInfo); content undocumented, not used.</summary>
    SystemInfo = 0x03,

    /// <summary>Sequence control relays S (HslCommunication only).</summary>
    S = 0x04,

    /// <summary>Special memory SM ("system flags of 200 family").</summary>
    SM = 0x05,

    /// <summary>Analog inputs AIW ("analog inputs of 200 family"), read by words.</summary>
    AI = 0x06,

    /// <summary>Analog outputs AQW ("analog outputs of 200 family"), by words.</summary>
    AQ = 0x07,

    /// <summary>Counters C0-C255 ("IEC counters (200 family)"): item address = counter number.</summary>
    C = 0x1E,

    /// <summary>Timers T0-T255 ("IEC timers (200 family)"): item address = timer number.</summary>
    T = 0x1F,

    I = 0x81,
    Q = 0x82,
    M = 0x83,

    /// <summary>V memory, addressed as data block 1 ("the command transmitted is exactly the same that would read DB1", libnodave testPPI.c).</summary>
    V = 0x84,
}
