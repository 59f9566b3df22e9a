namespace OperatorPanel.Core.Ppi.S7;

/// <summary>
/// The "transport size" byte of a data item, saying how its length counts (libnodave _daveTestResultData; captures in
/// docs/ppi.md section 5): 16#04 length in bits, 16#03 bits with one byte per bit, 16#09 length in bytes.
/// </summary>
public enum S7DataSize : byte
{
    None = 0x00,
    Bit = 0x03,
    Bits = 0x04,
    OctetString = 0x09,
}
