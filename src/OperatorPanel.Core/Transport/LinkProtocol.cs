namespace OperatorPanel.Core.Transport;

/// <summary>What a bus speaks: our handler's Freeport frames, or the CPU's own PPI (docs/ppi.md).</summary>
public enum LinkProtocol
{
    /// <summary>The generated handler answers the panel's frames (docs/protocol-v2.md): change-only refresh, radio modules.</summary>
    Freeport,

    /// <summary>The CPU answers PPI itself: no program of ours in the PLC; 9600, 19200 or 187500 baud, 8 data bits, even parity.</summary>
    Ppi,
}
