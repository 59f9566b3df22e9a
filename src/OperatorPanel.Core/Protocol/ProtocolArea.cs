using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Core.Protocol;

/// <summary>Area codes on the wire (docs/protocol-v2.md, "Areas").</summary>
public enum ProtocolArea : byte
{
    I = 0x01,
    Q = 0x02,
    M = 0x03,
    V = 0x04,
    SM = 0x05,
}

public static class ProtocolAreaExtensions
{
    public static MemoryArea ToMemoryArea(this ProtocolArea area) => area switch
    {
        ProtocolArea.I => MemoryArea.I,
        ProtocolArea.Q => MemoryArea.Q,
        ProtocolArea.M => MemoryArea.M,
        ProtocolArea.V => MemoryArea.V,
        ProtocolArea.SM => MemoryArea.SM,
    };

    /// <summary>The wire code of an area the link serves; null for areas the protocol does not carry.</summary>
    public static ProtocolArea? FromMemoryArea(MemoryArea area) => area switch
    {
        MemoryArea.I => ProtocolArea.I,
        MemoryArea.Q => ProtocolArea.Q,
        MemoryArea.M => ProtocolArea.M,
        MemoryArea.V => ProtocolArea.V,
        MemoryArea.SM => ProtocolArea.SM,
        MemoryArea.S or MemoryArea.T or MemoryArea.C or MemoryArea.AI or MemoryArea.AQ or MemoryArea.AC or MemoryArea.HC or MemoryArea.L => null,
    };
}
