namespace OperatorPanel.Core.Ppi.S7;

/// <summary>
/// The "transport size" byte of a data item, saying how its length counts (libnodave _daveTestResultData; the Wireshark
/// s7comm dissector's S7COMM_DATA_TRANSPORT_SIZE_*; captures in docs/ppi.md section 5): 16#03 bit, 16#04 and 16#05
/// length in bits, 16#06, 16#07 and 16#09 length in bytes. The S7-200 answers with 16#03, 16#04 and 16#09.
/// </summary>
public enum S7DataSize : byte
{
    None = 0x00,
    Bit = 0x03,
    Bits = 0x04,
    Integer = 0x05,
    DoubleInteger = 0x06,
    Real = 0x07,
    OctetString = 0x09,
}
