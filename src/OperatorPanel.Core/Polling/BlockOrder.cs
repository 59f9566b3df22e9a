using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Core.Polling;

/// <summary>
/// The two orders the planner sorts blocks in, as plain comparisons: a station's blocks never share an address, so both
/// are total and an unstable Array.Sort gives the same result as LINQ's OrderBy chains at a fraction of the cost (the
/// planner sorts once per tail budget it tries).
/// </summary>
internal static class BlockOrder
{
    /// <summary>Area, then offset.</summary>
    public static int ByAddress(ReadItem a, ReadItem b) => a.Area != b.Area ? a.Area.CompareTo(b.Area) : a.Offset.CompareTo(b.Offset);

    /// <summary>Longest first, then area and offset.</summary>
    public static int LongestFirst(ReadItem a, ReadItem b) => a.Length != b.Length ? b.Length.CompareTo(a.Length) : ByAddress(a, b);

    /// <summary>The blocks as a new array in <paramref name="order"/>.</summary>
    public static ReadItem[] Sorted(IEnumerable<ReadItem> blocks, Comparison<ReadItem> order)
    {
        var sorted = blocks.ToArray();
        Array.Sort(sorted, order);
        return sorted;
    }
}
