using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Core.Cpu;

/// <summary>One addressable memory area of a CPU: its size in bytes, counted from byte 0.</summary>
public sealed record CpuArea(MemoryArea Area, int ByteCount)
{
    public int LastByte => ByteCount - 1;
}
