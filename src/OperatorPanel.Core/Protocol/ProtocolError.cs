namespace OperatorPanel.Core.Protocol;

/// <summary>Status byte of a reply (docs/protocol-v2.md, "Error replies"). 00 is success.</summary>
public enum ProtocolError : byte
{
    None = 0x00,

    /// <summary>Named for logs only: a frame that fails its frame check is never answered.</summary>
    BadChecksum = 0x01,
    AddressOutOfRange = 0x02,
    NotWritable = 0x03,
    BadLength = 0x04,
    UnknownCommand = 0x05,
    BadParameter = 0x06,

    /// <summary>READ LIST or READ CHANGES of a list that was never defined, or was cleared (invalidation, STOP, power-up).</summary>
    ListNotDefined = 0x07,
}
