using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Protocol.V3;

namespace OperatorPanel.Core.Protocol;

/// <summary>
/// Bytes the protocol 3 handler refuses to write although the CPU would take them (docs/protocol.md section 2, WRITE:
/// 83): its own V bytes, by default the top of V (<see cref="HandlerShape.DefaultVFirst"/>; the full handler's range
/// holds the compact one's). SM it never writes at all (<see cref="LinkAreas"/>). Where a station's handler really keeps
/// its bytes the PC learns from IDENTIFY (V_FIRST, V_BYTES); this is what <c>opanel address</c> can say without a PLC.
/// </summary>
public static class HandlerProtection
{
    /// <summary>Null when a handler generated with the default settings writes <paramref name="address"/>; otherwise why not.</summary>
    public static string? Refusal(PlcAddress address, CpuProfile cpu)
    {
        ArgumentNullException.ThrowIfNull(cpu);
        if (address.Area != MemoryArea.V || !cpu.TryGetArea(MemoryArea.V, out var v))
        {
            return null;
        }

        var full = HandlerShape.Full.DefaultVFirst(v.ByteCount);
        var compact = HandlerShape.Compact.DefaultVFirst(v.ByteCount);
        return address.ByteOffset <= v.LastByte && address.LastByte >= full
            ? $"{address} is in the handler's own V bytes VB{full}-VB{v.LastByte} (where generate puts the full handler's buffer, work bytes and list by default; "
                + $"the compact handler's are VB{compact}-VB{v.LastByte}; IDENTIFY says where a station's are)"
            : null;
    }
}
