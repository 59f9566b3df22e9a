using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Protocol;
using OperatorPanel.StlGen.Handler;

namespace OperatorPanel.StlGen.Options;

/// <summary>Defaults chosen to fit beside an existing program.</summary>
public static class HandlerDefaults
{
    /// <summary>Q, M, V and SM writable (protocol area codes 2-5), as the reference model's default.</summary>
    public const int WriteMask = 0x3C;

    /// <summary>
    /// READ CHANGES copies: 120 bytes hold the copy of one list of the largest READ reply or of several smaller lists,
    /// about a third of what the buffer and work bytes take already.
    /// </summary>
    public const int CopyBytes = 120;

    /// <summary>The 256-byte receive/transmit buffer (byte 0 = count), the work bytes and <paramref name="copyBytes"/> copy bytes.</summary>
    public static int FootprintBytes(int copyBytes) => HandlerMemory.BufferBytes + HandlerLayout.WorkBytes + copyBytes;

    /// <summary>
    /// The top of V memory: user programs grow from VB0 upwards, so the end of V is the place least likely to be in
    /// use. The footprint ends at the last V byte, starting on an even byte (words and double words stay aligned).
    /// </summary>
    public static int BufferStart(CpuProfile cpu, int copyBytes = CopyBytes)
    {
        ArgumentNullException.ThrowIfNull(cpu);
        return (VBytes(cpu) - FootprintBytes(copyBytes)) & ~1;
    }

    /// <summary>Version 3: the top of V for the full or compact handler, on an even byte.</summary>
    public static int V3First(CpuProfile cpu, bool compact)
    {
        ArgumentNullException.ThrowIfNull(cpu);
        return (compact ? Core.Protocol.V3.HandlerShape.Compact : Core.Protocol.V3.HandlerShape.Full).DefaultVFirst(VBytes(cpu));
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

    /// <summary>INT125 on, for the same reason as the subroutine: protocol 2 takes INT125-INT127, protocol 3 INT125-INT126 and leaves INT127 free.</summary>
    public static int FirstInterrupt(CpuProfile cpu)
    {
        ArgumentNullException.ThrowIfNull(cpu);
        return cpu.InterruptRoutines - HandlerLayout.Interrupts;
    }

    internal static int VBytes(CpuProfile cpu) =>
        cpu.TryGetArea(Core.Addressing.MemoryArea.V, out var v) ? v.ByteCount : 0;
}
