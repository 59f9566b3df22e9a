namespace OperatorPanel.Core.Ppi.S7;

/// <summary>
/// The unit an item address counts in (libnodave doc/pdu.html "transport size or unit size 1=single bit, 2=byte,
/// 4=word"; for timers and counters the area code itself, daveAddToReadRequest).
/// </summary>
public enum S7TransportSize : byte
{
    /// <summary>One bit; count must be 1 (the S7-200 answers 16#03 otherwise, libnodave nodave.h).</summary>
    Bit = 0x01,

    Byte = 0x02,

    /// <summary>Words: the S7-200's analog areas are read and written this way (libnodave daveAddToReadRequest).</summary>
    Word = 0x04,

    Counter = 0x1E,

    Timer = 0x1F,
}
