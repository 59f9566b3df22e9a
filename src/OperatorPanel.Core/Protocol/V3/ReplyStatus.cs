namespace OperatorPanel.Core.Protocol.V3;

/// <summary>
/// The first byte after a reply's LEN (docs/protocol.md section 3). Bit 7 is always set, so a reply's byte 2 never
/// equals a station address (1-126) and no station takes an overheard reply for a request to it.
/// </summary>
public enum ReplyStatus : byte
{
    /// <summary>Done; the command's payload follows (READ LIST: the whole list).</summary>
    Ok = 0x80,

    /// <summary>READ LIST: no byte of the list differs from the copy; no payload.</summary>
    Unchanged = 0x81,
    AddressOutOfRange = 0x82,
    NotWritable = 0x83,
    BadLength = 0x84,
    UnknownCommand = 0x85,
    BadParameter = 0x86,
    ListNotDefined = 0x87,

    /// <summary>READ LIST: the changed double words of the list follow, INDEX and 4 bytes each.</summary>
    Changes = 0x88,
}

public static class ReplyStatusExtensions
{
    /// <summary>An error reply (02-07 with bit 7): the request was refused and carries no payload.</summary>
    public static bool IsError(this ReplyStatus status) => status is >= ReplyStatus.AddressOutOfRange and <= ReplyStatus.ListNotDefined;
}
