using System.Collections.Immutable;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Core.Polling;

/// <summary>Packs one station's blocks into READ frames: first fit, longest block first.</summary>
internal static class FramePacker
{
    /// <summary>
    /// Frames whose item count and data bytes each fit <paramref name="capacity"/> (for a plain READ: at most 20 items and
    /// a data capacity that shrinks with every further item). Items inside a frame, and frames, in area and offset
    /// order. Each frame keeps its running totals, and a full frame leaves the scan.
    /// </summary>
    public static List<ImmutableArray<ReadItem>> Pack(IReadOnlyCollection<ReadItem> blocks, FrameCapacity capacity)
    {
        var frames = new List<OpenFrame>();
        var open = new List<OpenFrame>();
        foreach (var block in BlockOrder.Sorted(blocks, BlockOrder.LongestFirst))
        {
            var index = open.FindIndex(f => capacity.Fits(f.Items.Count + 1, f.DataBytes + block.Length));
            var frame = index >= 0 ? open[index] : new OpenFrame();
            if (index < 0)
            {
                frames.Add(frame);
                open.Add(frame);
                index = open.Count - 1;
            }

            frame.Items.Add(block);
            frame.DataBytes += block.Length;

            // A frame that cannot take even one more byte is never looked at again: the scan stays short.
            if (!capacity.Fits(frame.Items.Count + 1, frame.DataBytes + 1))
            {
                open.RemoveAt(index);
            }
        }

        var packed = frames.Select(f => ImmutableArray.Create(BlockOrder.Sorted(f.Items, BlockOrder.ByAddress))).ToList();
        packed.Sort((a, b) => BlockOrder.ByAddress(a[0], b[0]));
        return packed;
    }

    private sealed class OpenFrame
    {
        public List<ReadItem> Items { get; } = [];

        public int DataBytes { get; set; }
    }
}
