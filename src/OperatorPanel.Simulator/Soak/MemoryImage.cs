using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Simulator.Reference;

namespace OperatorPanel.Simulator.Soak;

/// <summary>
/// A copy of some byte ranges of the PLC's memory (<see cref="WatchedBytes"/>) that the judge brings forward change by
/// change (<see cref="Apply"/>), to know what every watched address held after each one.
/// </summary>
public sealed class MemoryImage
{
    private readonly List<(WatchedBytes Range, byte[] Bytes)> _ranges;

    public MemoryImage(IEnumerable<(WatchedBytes Range, byte[] Bytes)> ranges)
    {
        ArgumentNullException.ThrowIfNull(ranges);
        _ranges = [.. ranges.Select(r => r.Bytes.Length == r.Range.Count
            ? (r.Range, r.Bytes.ToArray())
            : throw new ArgumentException($"{r.Range} needs {r.Range.Count} bytes, not {r.Bytes.Length}", nameof(ranges)))];
    }

    public IEnumerable<WatchedBytes> Ranges => _ranges.Select(r => r.Range);

    /// <summary>The <paramref name="ranges"/> of <paramref name="memory"/> as they are now.</summary>
    public static MemoryImage Snapshot(PlcMemory memory, IEnumerable<WatchedBytes> ranges)
    {
        ArgumentNullException.ThrowIfNull(memory);
        ArgumentNullException.ThrowIfNull(ranges);
        return new(ranges.Select(r => (r, memory.Area(r.Area).AsSpan(r.First, r.Count).ToArray())));
    }

    public MemoryImage Copy() => new(_ranges);

    /// <summary>True when every byte of <paramref name="address"/> lies in one of the ranges.</summary>
    public bool Covers(PlcAddress address) => TryFind(SoakRegion.AreaOf(address), address.ByteOffset, address.LastByte, out _);

    /// <summary>What <paramref name="address"/> holds: its bytes, big-endian; 00 or 01 for a bit (as the panel's values hold it).</summary>
    public ImmutableArray<byte> Read(PlcAddress address)
    {
        if (!TryFind(SoakRegion.AreaOf(address), address.ByteOffset, address.LastByte, out var range))
        {
            throw new ArgumentOutOfRangeException(nameof(address), address, "outside the watched bytes");
        }

        var bytes = range.Bytes.AsSpan(address.ByteOffset - range.Range.First, address.LastByte - address.ByteOffset + 1);
        return address.Bit is { } bit ? [(byte)((bytes[0] >> bit) & 1)] : [.. bytes];
    }

    /// <summary>Brings the copy to the state after <paramref name="change"/>, which lies in one range (the observer records it so).</summary>
    public void Apply(MemoryChange change)
    {
        ArgumentNullException.ThrowIfNull(change);
        if (!TryFind(change.Area, change.First, change.Last, out var range))
        {
            throw new ArgumentOutOfRangeException(nameof(change), change, "outside the watched bytes");
        }

        change.After.AsSpan().CopyTo(range.Bytes.AsSpan(change.First - range.Range.First));
    }

    private bool TryFind(ProtocolArea area, int first, int last, out (WatchedBytes Range, byte[] Bytes) found)
    {
        foreach (var range in _ranges)
        {
            if (range.Range.Area == area && first >= range.Range.First && last < range.Range.First + range.Range.Count)
            {
                found = range;
                return true;
            }
        }

        found = default;
        return false;
    }
}
