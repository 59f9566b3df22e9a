using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Core.Polling;

/// <summary>
/// One station's watched bytes, prepared once per plan: the coalesced ranges (no gap read) and the ranges bridged for
/// plain READs (<see cref="RangeMerger.Cheapest"/>). Split into blocks, longest first, per block length on demand.
/// </summary>
internal sealed class StationBlocks
{
    private readonly List<ReadItem> _ranges;
    private readonly List<ReadItem> _bridged;
    private readonly Dictionary<(bool, int), ImmutableArray<ReadItem>> _split = [];

    private StationBlocks(Station station, List<ReadItem> ranges, List<ReadItem> bridged)
    {
        Station = station;
        _ranges = ranges;
        _bridged = bridged;
    }

    public Station Station { get; }

    public static StationBlocks Of(Station station, IEnumerable<ReadItem> spans, PollCostModel model)
    {
        var ranges = RangeMerger.Coalesce(spans);
        return new StationBlocks(station, ranges, RangeMerger.Cheapest(ranges, model, model.PlainCapacity(0)));
    }

    /// <summary>The coalesced ranges, cut at <paramref name="maxLength"/>, longest first.</summary>
    public ImmutableArray<ReadItem> RangesLongestFirst(int maxLength) => Blocks(false, maxLength);

    /// <summary>The bridged ranges, cut at <paramref name="maxLength"/>, longest first.</summary>
    public ImmutableArray<ReadItem> BridgedLongestFirst(int maxLength) => Blocks(true, maxLength);

    private ImmutableArray<ReadItem> Blocks(bool bridged, int maxLength)
    {
        if (!_split.TryGetValue((bridged, maxLength), out var blocks))
        {
            blocks = [.. BlockOrder.Sorted(RangeMerger.Split(bridged ? _bridged : _ranges, maxLength), BlockOrder.LongestFirst)];
            _split[(bridged, maxLength)] = blocks;
        }

        return blocks;
    }
}
