namespace OperatorPanel.Core.Protocol.V3;

/// <summary>Command codes of protocol v3: the low 4 bits of a request's SEQ/CMD byte (docs/protocol.md section 2).</summary>
public enum Command : byte
{
    Identify = 0x1,
    Read = 0x2,
    Write = 0x3,

    /// <summary>Sets the bits of a mask in one byte to a value's (AND/OR on the byte itself).</summary>
    WriteBits = 0x4,

    /// <summary>Stores the station's list: its items, whose bytes follow one another in the list data (full handler only).</summary>
    DefineList = 0x5,

    /// <summary>The list's changes since the handler's copy: UNCHANGED, CHANGES or the whole list (full handler only).</summary>
    ReadList = 0x6,

    /// <summary>The whole list; leaves the handler's copy not valid, so the next READ LIST answers whole too (full handler only).</summary>
    ReadListFull = 0x7,

    /// <summary>Puts the CPU into STOP (only in a handler generated with STOP).</summary>
    Stop = 0x8,
}
