using System.Buffers.Binary;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Simulator.Soak;

/// <summary>
/// The double words of V the soak writes and reads: VD<see cref="First"/>, VD<see cref="First"/>+4, ... <see cref="Count"/>
/// of them, away from the handler's own bytes. Values are big-endian, as the S7-200 stores them.
/// </summary>
public sealed record SoakRegion(int First, int Count)
{
    /// <summary>
    /// VD1000 and VD1004, below the handler's buffer on every CPU with that much V. Small on purpose: at 1% of bits
    /// flipped a frame of n characters arrives whole with probability 0.99^(8n), 6.5% for the 34-character v2 READ
    /// reply of these 8 bytes, 0.001% for the 146 characters of 64 bytes.
    /// </summary>
    public static SoakRegion Default { get; } = new(1000, 2);

    public int Bytes => Count * 4;

    public IReadOnlyList<int> Slots => [.. Enumerable.Range(0, Count).Select(i => First + (4 * i))];

    public uint Read(ReadOnlySpan<byte> regionBytes, int slot) => BinaryPrimitives.ReadUInt32BigEndian(regionBytes[(slot - First)..]);

    /// <summary>
    /// Applies the part of a change that falls in the region to the region's copy; false when any of the change lies
    /// outside the region (another area, or V bytes the soak never writes).
    /// </summary>
    public bool Apply(MemoryChange change, Span<byte> regionBytes)
    {
        ArgumentNullException.ThrowIfNull(change);
        if (change.Area != ProtocolArea.V)
        {
            return false;
        }

        var from = Math.Max(change.First, First);
        var to = Math.Min(change.Last, First + Bytes - 1);
        if (from <= to)
        {
            change.After.AsSpan(from - change.First, to - from + 1).CopyTo(regionBytes[(from - First)..]);
        }

        return change.First >= First && change.Last < First + Bytes;
    }
}
