namespace OperatorPanel.Core.Addressing;

/// <summary>S7-200 data memory areas, named as the manual writes their operands.</summary>
public enum MemoryArea
{
    /// <summary>Process-image inputs (I, IB, IW, ID).</summary>
    I,
    /// <summary>Process-image outputs (Q, QB, QW, QD).</summary>
    Q,
    /// <summary>Bit memory, "internal relays" (M, MB, MW, MD).</summary>
    M,
    /// <summary>Variable memory (V, VB, VW, VD).</summary>
    V,
    /// <summary>Special memory (SM, SMB, SMW, SMD); SMB0-SMB29 are read-only.</summary>
    SM,
    /// <summary>Sequence control relays (S, SB, SW, SD).</summary>
    S,
    /// <summary>Timers (T0-T255).</summary>
    T,
    /// <summary>Counters (C0-C255).</summary>
    C,
    /// <summary>Analog input words (AIW, read-only, even offsets).</summary>
    AI,
    /// <summary>Analog output words (AQW, write-only on the CPU, even offsets).</summary>
    AQ,
    /// <summary>Accumulators AC0-AC3.</summary>
    AC,
    /// <summary>High-speed counters HC0-HC5.</summary>
    HC,
    /// <summary>Local memory of a program organisation unit (L, LB, LW, LD).</summary>
    L,
}
