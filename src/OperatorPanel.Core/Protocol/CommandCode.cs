namespace OperatorPanel.Core.Protocol;

/// <summary>Command codes on the wire; a reply carries the code with bit 7 set (docs/protocol.md).</summary>
public enum CommandCode : byte
{
    Identify = 0x01,
    Read = 0x02,
    Write = 0x03,
    WriteBit = 0x04,
}
