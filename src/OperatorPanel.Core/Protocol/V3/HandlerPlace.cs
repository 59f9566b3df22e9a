using System.Globalization;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;

namespace OperatorPanel.Core.Protocol.V3;

/// <summary>
/// Where a protocol 3 handler's V bytes (V_FIRST and V_BYTES of its <see cref="HandlerShape"/>) may lie: the one rule
/// behind the generator's STL005 (<c>generate --buffer</c>, Generate PLC code's buffer start) and a station's
/// <c>"handlerVFirst"</c> in the project file, so the project cannot record a place the generator refuses.
/// </summary>
public static class HandlerPlace
{
    /// <summary>
    /// The lowest V_FIRST: the frame check walks from a pointer 3 bytes before the handler's bytes (&amp;VB(V_FIRST - 3)
    /// plus the byte count, docs/protocol.md section 6), and an S7-200 address has no negative byte.
    /// </summary>
    public const int LowestVFirst = 3;

    /// <summary>The highest V_FIRST on a V area of <paramref name="vAreaBytes"/>: the handler's last byte is V's last.</summary>
    public static int HighestVFirst(HandlerShape shape, int vAreaBytes)
    {
        ArgumentNullException.ThrowIfNull(shape);
        return vAreaBytes - shape.VBytes;
    }

    /// <summary>The first and last V byte of a handler of <paramref name="shape"/> starting at <paramref name="vFirst"/>.</summary>
    public static (int First, int Last) Range(int vFirst, HandlerShape shape)
    {
        ArgumentNullException.ThrowIfNull(shape);
        return (vFirst, vFirst + shape.VBytes - 1);
    }

    /// <summary>
    /// Null when a handler of <paramref name="shape"/> fits at <paramref name="vFirst"/> in <paramref name="cpu"/>'s V;
    /// otherwise what it would need and what the CPU has ("the handler needs VB2-VB607 (606 bytes) but the CPU 224 has
    /// VB0-VB8191 and a protocol 3 handler starts at VB3 or later (...)"), for the caller to add the allowed range in
    /// its own words (<see cref="HighestVFirst"/>).
    /// </summary>
    public static string? Problem(int vFirst, HandlerShape shape, CpuProfile cpu)
    {
        ArgumentNullException.ThrowIfNull(shape);
        ArgumentNullException.ThrowIfNull(cpu);
        var vBytes = VBytes(cpu);
        var (first, last) = Range(vFirst, shape);
        if (first >= LowestVFirst && last < vBytes)
        {
            return null;
        }

        var low = first >= 0 && first < LowestVFirst
            ? " and a protocol 3 handler starts at VB3 or later (its frame check points 3 bytes before its V bytes)"
            : string.Empty;
        return string.Create(CultureInfo.InvariantCulture,
            $"the handler needs VB{first}-VB{last} ({shape.VBytes} bytes) but the {cpu.DisplayName} has VB0-VB{vBytes - 1}{low}");
    }

    /// <summary>The size of <paramref name="cpu"/>'s V area; 0 for a CPU without one.</summary>
    public static int VBytes(CpuProfile cpu)
    {
        ArgumentNullException.ThrowIfNull(cpu);
        return cpu.TryGetArea(MemoryArea.V, out var v) ? v.ByteCount : 0;
    }
}
