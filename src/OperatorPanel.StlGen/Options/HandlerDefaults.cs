using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Protocol;
using OperatorPanel.StlGen.Handler;

namespace OperatorPanel.StlGen.Options;

/// <summary>Defaults chosen to fit beside an existing program.</summary>
public static class HandlerDefaults
{
    /// <summary>Q, M, V and SM writable (protocol area codes 2-5), as the reference model's default.</summary>
    public const int WriteMask = 0x3C;

    /// <summary>The 256-byte receive/transmit buffer (byte 0 = count) plus the work bytes.</summary>
    public const int FootprintBytes = HandlerMemory.BufferBytes + HandlerLayout.WorkBytes;

    /// <summary>
    /// The top of V memory: user programs grow from VB0 upwards, so the end of V is the place least likely to be in
    /// use. The footprint ends at the last V byte, starting on an even byte (words and double words stay aligned).
    /// </summary>
    public static int BufferStart(CpuProfile cpu)
    {
        ArgumentNullException.ThrowIfNull(cpu);
        return (VBytes(cpu) - FootprintBytes) & ~1;
    }

    /// <summary>
    /// The last subroutine number of the CPU (SBR63 on CPU 221/222/224, SBR127 on 224XP/226; docs/sources/s7200-facts.md
    /// section 1): Micro/WIN numbers new subroutines upwards from SBR0, so the top is free in nearly every program.
    /// </summary>
    public static int FirstSubroutine(CpuProfile cpu)
    {
        ArgumentNullException.ThrowIfNull(cpu);
        return cpu.Subroutines - HandlerLayout.Subroutines;
    }

    /// <summary>INT125-INT127, the top three of the 128 interrupt routines, for the same reason as the subroutine.</summary>
    public static int FirstInterrupt(CpuProfile cpu)
    {
        ArgumentNullException.ThrowIfNull(cpu);
        return cpu.InterruptRoutines - HandlerLayout.Interrupts;
    }

    internal static int VBytes(CpuProfile cpu) =>
        cpu.TryGetArea(Core.Addressing.MemoryArea.V, out var v) ? v.ByteCount : 0;
}
