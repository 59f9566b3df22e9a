using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Simulator.Soak;

/// <summary>
/// The addresses the soak watches, and writes where the Freeport link writes (<see cref="LinkAreas.Writes"/>: Q, M and V;
/// I is read only; SM the handler does not serve, docs/protocol.md section 1.3). Words and double words are big-endian, as the S7-200 stores them.
/// </summary>
public sealed record SoakRegion(ImmutableArray<PlcAddress> Items)
{
    /// <summary>VD1000 and VD1004: the soak's region until it reached the area ends, away from every area's end.</summary>
    public static SoakRegion MiddleOfV { get; } = new([DoubleWord(MemoryArea.V, 1000), DoubleWord(MemoryArea.V, 1004)]);

    /// <summary>The items of <see cref="Items"/> the Freeport link writes, in order.</summary>
    public ImmutableArray<PlcAddress> Written => [.. Items.Where(a => LinkAreas.Writes(LinkProtocol.Freeport, a.Area))];

    /// <summary>
    /// <see cref="MiddleOfV"/> and items of every width at the end of each area the Freeport link reaches on
    /// <paramref name="cpu"/>, so that the ranges a list holds end there: the panel widens a range shorter than a list
    /// item's 4-byte window backward when the window would pass its area's end (Protocol/V3/ListPlan), which is where
    /// QW14, MW30 and MB31 were shown good with the wrong bytes. On a CPU 226 with the handler at VB9634:
    /// <list type="bullet">
    /// <item>V: VD9630, VW9632, VB9633, V9633.0, one range ending at the last byte below the handler's own (the
    /// highest V the panel may write; V itself ends in the handler's bytes, which change with every frame);</item>
    /// <item>Q: QW14, QB15, Q15.7, a 2-byte range widened to QB12-QB15;</item>
    /// <item>M: MD20 and MB29, MW30, M31.7, a 3-byte range widened to MB28-MB31 beside a double word of its own in the
    /// same frame (MB24-MB28 between: too many bytes for the planner to read over);</item>
    /// <item>I (read only): IB15, I15.0, a 1-byte range widened to IB12-IB15 (the window of the list's filler items, too).</item>
    /// </list>
    /// </summary>
    public static SoakRegion AreaEnds(CpuProfile cpu, int handlerFirstByte)
    {
        ArgumentNullException.ThrowIfNull(cpu);
        var q = Bytes(cpu, MemoryArea.Q);
        var m = Bytes(cpu, MemoryArea.M);
        var i = Bytes(cpu, MemoryArea.I);
        var v = handlerFirstByte;
        return new(
        [
            .. MiddleOfV.Items,
            DoubleWord(MemoryArea.V, v - 4), Word(MemoryArea.V, v - 2), Byte(MemoryArea.V, v - 1), PlcAddress.ForBit(MemoryArea.V, v - 1, 0),
            Word(MemoryArea.Q, q - 2), Byte(MemoryArea.Q, q - 1), PlcAddress.ForBit(MemoryArea.Q, q - 1, 7),
            DoubleWord(MemoryArea.M, m - 12), Byte(MemoryArea.M, m - 3), Word(MemoryArea.M, m - 2), PlcAddress.ForBit(MemoryArea.M, m - 1, 7),
            Byte(MemoryArea.I, i - 1), PlcAddress.ForBit(MemoryArea.I, i - 1, 0),
        ]);
    }

    /// <summary>The addresses in the order given, as the figures print them: "VD1000 VD1004 ...".</summary>
    public override string ToString() => string.Join(" ", Items);

    private static int Bytes(CpuProfile cpu, MemoryArea area) =>
        cpu.TryGetArea(area, out var range) ? range.ByteCount : throw new ArgumentException($"{cpu.DisplayName} has no {area}", nameof(cpu));

    private static PlcAddress Byte(MemoryArea area, int offset) => PlcAddress.ForBytes(area, offset, AccessWidth.Byte);

    private static PlcAddress Word(MemoryArea area, int offset) => PlcAddress.ForBytes(area, offset, AccessWidth.Word);

    private static PlcAddress DoubleWord(MemoryArea area, int offset) => PlcAddress.ForBytes(area, offset, AccessWidth.DoubleWord);

    /// <summary>The protocol's area of <paramref name="address"/>: every soak item is in one the Freeport link reads.</summary>
    internal static ProtocolArea AreaOf(PlcAddress address) =>
        ProtocolAreaExtensions.FromMemoryArea(address.Area) ?? throw new ArgumentException($"{address}: not an area the Freeport link reads", nameof(address));
}
