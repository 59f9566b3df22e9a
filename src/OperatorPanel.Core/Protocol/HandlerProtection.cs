using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;

namespace OperatorPanel.Core.Protocol;

/// <summary>
/// Bytes the handler refuses to write although the CPU would take them (docs/protocol-v2.md, error 03 "not writable"): its
/// port's Freeport control byte (SMB30 for port 0, SMB130 for port 1), its port's receive message control
/// (SMB86-SMB94, SMB186-SMB194), the timed interrupt 0 interval SMB34 (its reply delay), and its own V bytes, by default
/// the last V_BYTES of V (<see cref="HandlerMemory"/>). The handler serves one port; which one, and where its V bytes
/// are, the PC learns from IDENTIFY (PORT, V_FIRST, V_BYTES) or assumes the generator's defaults.
/// </summary>
public static class HandlerProtection
{
    /// <summary>Null when a handler on <paramref name="port"/> with default V bytes writes <paramref name="address"/>; otherwise why not.</summary>
    public static string? Refusal(PlcAddress address, CpuProfile cpu, int port = 0, int copyBytes = HandlerMemory.DefaultCopyBytes)
    {
        ArgumentNullException.ThrowIfNull(cpu);
        var (first, last) = (address.ByteOffset, address.LastByte);
        bool Touches(int from, int to) => first <= to && last >= from;
        var offset = 100 * port;
        string Is(int from) => address.Width == AccessWidth.Byte && first == from ? $"{address} is" : $"{address} touches SMB{from}, which is";
        if (address.Area == MemoryArea.SM)
        {
            return Touches(30 + offset, 30 + offset) ? $"{Is(30 + offset)} port {port}'s Freeport control byte, which the handler sets"
                : Touches(86 + offset, 94 + offset) ? $"{address} is in port {port}'s receive message control SMB{86 + offset}-SMB{94 + offset}, which the handler's RCV uses"
                : Touches(34, 34) ? $"{Is(34)} the timed interrupt 0 interval, the handler's reply delay"
                : null;
        }

        if (address.Area == MemoryArea.V && cpu.TryGetArea(MemoryArea.V, out var v))
        {
            var vFirst = v.ByteCount - HandlerMemory.VBytes(copyBytes);
            return Touches(vFirst, v.LastByte)
                ? $"{address} is in the handler's own V bytes VB{vFirst}-VB{v.LastByte} (frame buffer, work bytes, READ CHANGES copies; where generate puts them by default)"
                : null;
        }

        return null;
    }
}
