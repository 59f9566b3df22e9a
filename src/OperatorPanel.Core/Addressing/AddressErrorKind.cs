namespace OperatorPanel.Core.Addressing;

/// <summary>Why an address text or an address was refused.</summary>
public enum AddressErrorKind
{
    Empty,
    UnknownArea,
    MissingByteNumber,
    ByteNumberTooLarge,
    MissingBitNumber,
    BitOutOfRange,
    UnexpectedBitNumber,
    WidthNotAllowed,
    OddAnalogOffset,
    TrailingText,
    AreaNotOnCpu,
    OutOfRange,
    NotWritable,
}
