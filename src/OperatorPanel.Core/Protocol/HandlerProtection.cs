using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Protocol.V3;

namespace OperatorPanel.Core.Protocol;

/// <summary>
/// Bytes the protocol 3 handler refuses to write although the CPU would take them (docs/protocol.md section 2, WRITE:
/// 83): its own V bytes, by default the top of V (<see cref="HandlerShape.DefaultVFirst"/>; the full handler's range
/// holds the compact one's), or where the project's "handlerVFirst" says a station's handler was generated. SM it never
/// writes at all (<see cref="LinkAreas"/>). Where a station's handler really keeps its bytes the PC learns from IDENTIFY
/// (V_FIRST, V_BYTES); the project records whether it is compact and, when moved, its V_FIRST, so this is what
/// <c>opanel address</c> and a write can say without asking the PLC.
/// </summary>
public static class HandlerProtection
{
    /// <summary>
    /// Null when a handler generated with the default settings writes <paramref name="address"/>; otherwise why not,
    /// naming the full handler's range and the compact one's (<c>opanel address</c>: it knows no station).
    /// </summary>
    public static string? Refusal(PlcAddress address, CpuProfile cpu)
    {
        ArgumentNullException.ThrowIfNull(cpu);
        if (OwnVBytes(cpu, compact: false) is not (var full, var last) || !Touches(address, full, last))
        {
            return null;
        }

        var (compact, _) = OwnVBytes(cpu, compact: true)!.Value;
        return $"{InOwnBytes(address, full, last)} (where generate puts the full handler's buffer, work bytes and list by default; "
            + $"the compact handler's are VB{compact}-VB{last}; IDENTIFY says where a station's are)";
    }

    /// <summary>
    /// Null when the station's handler, the full or the <paramref name="compact"/> one, writes <paramref name="address"/>;
    /// otherwise why not, naming that handler's range (a write's refusal). The handler is where the project's
    /// <paramref name="vFirst"/> says, or with none where generate puts it by default.
    /// </summary>
    public static string? Refusal(PlcAddress address, CpuProfile cpu, bool compact, int? vFirst = null)
    {
        ArgumentNullException.ThrowIfNull(cpu);
        if (OwnVBytes(cpu, compact, vFirst) is not (var first, var last) || !Touches(address, first, last))
        {
            return null;
        }

        var what = compact ? "the compact handler's buffer and work bytes" : "the full handler's buffer, work bytes and list";
        var where = vFirst is null
            ? $"where generate puts {what} by default"
            : $"where the project's \"handlerVFirst\" puts {what}";
        return $"{InOwnBytes(address, first, last)} ({where}; IDENTIFY says where a station's are)";
    }

    /// <summary>
    /// The first and last V byte of the handler starting at <paramref name="vFirst"/>, or with none of the handler
    /// generated with the default settings (the top of V); null for a CPU without V.
    /// </summary>
    public static (int First, int Last)? OwnVBytes(CpuProfile cpu, bool compact, int? vFirst = null)
    {
        ArgumentNullException.ThrowIfNull(cpu);
        if (!cpu.TryGetArea(MemoryArea.V, out var v))
        {
            return null;
        }

        var shape = HandlerShape.Of(compact);
        return vFirst is { } first ? HandlerPlace.Range(first, shape) : (shape.DefaultVFirst(v.ByteCount), v.LastByte);
    }

    private static bool Touches(PlcAddress address, int first, int last) =>
        address.Area == MemoryArea.V && address.ByteOffset <= last && address.LastByte >= first;

    private static string InOwnBytes(PlcAddress address, int first, int last) => $"{address} is in the handler's own V bytes VB{first}-VB{last}";
}
