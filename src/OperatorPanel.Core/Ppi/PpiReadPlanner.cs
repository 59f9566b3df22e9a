using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Ppi.S7;

namespace OperatorPanel.Core.Ppi;

/// <summary>
/// Packs addresses into as few read jobs as the PDU allows (docs/ppi.md section 8): per area the bytes (for T and C the
/// numbers) are merged into ranges (bridging gaps up to <see cref="PpiLimits.BridgeGap"/>) no longer than one item can
/// read, and the ranges fill jobs in address order while the request and its answer fit the PDU and the item limit.
/// </summary>
public static class PpiReadPlanner
{
    public static PpiReadPlan Plan(IEnumerable<PlcAddress> addresses, PpiLimits? limits = null)
    {
        ArgumentNullException.ThrowIfNull(addresses);
        limits ??= PpiLimits.Default;
        var rejected = ImmutableDictionary.CreateBuilder<PlcAddress, string>();
        var wanted = new List<PlcAddress>();
        foreach (var address in addresses.Distinct())
        {
            if (PpiAddressing.TryRead(address, out _, out var error))
            {
                wanted.Add(address);
            }
            else
            {
                rejected[address] = error;
            }
        }

        var ranges = wanted.GroupBy(a => a.Area).OrderBy(g => g.Key)
            .SelectMany(g => Ranges(g.Key, g, limits))
            .ToList();
        var requests = Pack(ranges, limits);
        return new PpiReadPlan(requests, Locate(wanted, requests), rejected.ToImmutable());
    }

    /// <summary>
    /// Merged ranges of one area, none longer than one item reads: bytes (whole words for AI and AQ), or for T and C
    /// elements of 5 answer bytes each, a gap bridged while it costs no more bytes than <see cref="PpiLimits.BridgeGap"/>.
    /// </summary>
    private static IEnumerable<S7Item> Ranges(MemoryArea area, IEnumerable<PlcAddress> addresses, PpiLimits limits)
    {
        var numbered = AreaSyntax.IsNumbered(area);
        var unit = numbered ? S7Item.TimerCounterBytes : 1;
        var longest = AreaSyntax.IsAnalog(area) ? limits.MaxReadBytes & ~1 : limits.MaxReadBytes / unit;
        var gap = limits.BridgeGap / unit;
        var merged = new List<(int First, int Last)>();
        foreach (var address in addresses.OrderBy(a => a.ByteOffset))
        {
            var (first, last) = (address.ByteOffset, numbered ? address.ByteOffset : address.LastByte);
            if (merged.Count > 0 && first - merged[^1].Last - 1 <= gap && last - merged[^1].First < longest)
            {
                merged[^1] = (merged[^1].First, Math.Max(merged[^1].Last, last));
            }
            else
            {
                merged.Add((first, last));
            }
        }

        foreach (var (first, last) in merged)
        {
            // Merging stops before a range outgrows one item, and no address is longer than 4 bytes: no range is cut.
            PpiAddressing.TryRange(area, first, last - first + 1, out var item, out _);
            yield return item;
        }
    }

    private static ImmutableArray<PpiReadRequest> Pack(List<S7Item> ranges, PpiLimits limits)
    {
        var requests = ImmutableArray.CreateBuilder<PpiReadRequest>();
        var current = new List<S7Item>();
        foreach (var range in ranges)
        {
            current.Add(range);
            if (current.Count > limits.MaxReadItems || S7AnswerCodec.ReadAnswerLength(current) > limits.PduSize)
            {
                current.RemoveAt(current.Count - 1);
                requests.Add(new PpiReadRequest([.. current]));
                current = [range];
            }
        }

        if (current.Count > 0)
        {
            requests.Add(new PpiReadRequest([.. current]));
        }

        return requests.ToImmutable();
    }

    private static ImmutableDictionary<PlcAddress, PpiSlice> Locate(List<PlcAddress> addresses, ImmutableArray<PpiReadRequest> requests)
    {
        var slices = ImmutableDictionary.CreateBuilder<PlcAddress, PpiSlice>();
        foreach (var address in addresses)
        {
            PpiAddressing.TryArea(address.Area, out var area);
            for (var r = 0; r < requests.Length && !slices.ContainsKey(address); r++)
            {
                var items = requests[r].Items;
                for (var i = 0; i < items.Length; i++)
                {
                    if (SliceIn(items[i], area, address) is { } slice)
                    {
                        slices[address] = new PpiSlice(r, i, slice.Offset, slice.Length);
                        break;
                    }
                }
            }
        }

        return slices.ToImmutable();
    }

    /// <summary>Where <paramref name="address"/>'s bytes are in <paramref name="item"/>'s answer; null when it is not there.</summary>
    private static (int Offset, int Length)? SliceIn(S7Item item, S7Area area, PlcAddress address)
    {
        if (item.Area != area)
        {
            return null;
        }

        if (item.IsTimerOrCounter)
        {
            var element = address.ByteOffset - item.Address;
            return element >= 0 && element < item.Count
                ? ((element * S7Item.TimerCounterBytes) + PpiAddressing.CurrentValueOffset, 2)
                : null;
        }

        var offset = address.ByteOffset - item.ByteOffset;
        return offset >= 0 && address.LastByte - item.ByteOffset < item.DataLength ? (offset, address.Width.ByteCount()) : null;
    }
}
