using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Simulator.Stl;

/// <summary>
/// The 32-bit value &amp; produces: area code in the high byte, byte offset in the low 24 bits. The S7-200's own
/// encoding is not in our sources (unconfirmed); programs only move pointers and add byte offsets (+D, INCD), which
/// this encoding supports unchanged.
/// </summary>
internal static class StlPointer
{
    public static uint Encode(MemoryArea area, int offset) => ((uint)(area + 1) << 24) | (uint)offset;

    /// <summary>The area (as (int)MemoryArea) and offset of a pointer, or area -1 when the high byte names no area.</summary>
    public static (int Area, int Offset) Decode(uint pointer) => ((int)(pointer >> 24) - 1, (int)(pointer & 0xFFFFFF));
}
