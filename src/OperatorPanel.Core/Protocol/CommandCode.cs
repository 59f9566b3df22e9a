namespace OperatorPanel.Core.Protocol;

/// <summary>Command codes on the wire; a reply carries the code with bit 7 set (docs/protocol-v2.md).</summary>
public enum CommandCode : byte
{
    Identify = 0x01,
    Read = 0x02,
    Write = 0x03,
    WriteBit = 0x04,

    /// <summary>Store a READ's item list in the handler's buffer tail under a list id (1-4).</summary>
    DefineList = 0x05,

    /// <summary>Read a stored list: a 12-character request instead of 12 + 8N.</summary>
    ReadList = 0x06,

    /// <summary>Put the CPU into STOP (only in a handler generated with STOP enabled; otherwise error 05).</summary>
    Stop = 0x07,

    /// <summary>Read a stored list as the bytes changed since the handler's copy, or whole (FULL).</summary>
    ReadChanges = 0x08,

    /// <summary>Read the changes of several stored lists (a mask) in one exchange; a list that cannot be answered so is marked REREAD.</summary>
    ReadChangesOfLists = 0x09,
}
