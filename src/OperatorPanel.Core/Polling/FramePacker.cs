using System.Collections.Immutable;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Core.Polling;

/// <summary>Packs one station's blocks into READ frames: first fit, longest block first.</summary>
internal static class FramePacker
{
    /// <summary>
    /// Frames that each fit <see cref="PollCostModel.Fits"/>: at most <see cref="PollCostModel.MaxItemsPerFrame"/>
    /// items, and a data capacity that shrinks by 2 bytes with every further item (2D + 4N &lt;= 243). Items inside a
    /// frame, and frames, in area and offset order.
    /// </summary>
    public static List<ImmutableArray<ReadItem>> Pack(IReadOnlyCollection<ReadItem> blocks, PollCostModel model)
    {
        var frames = new List<List<ReadItem>>();
        foreach (var block in blocks.OrderByDescending(b => b.Length).ThenBy(b => b.Area).ThenBy(b => b.Offset))
        {
            var frame = frames.Find(f => model.Fits(f.Count + 1, f.Sum(i => i.Length) + block.Length));
            if (frame is null)
            {
                frame = [];
                frames.Add(frame);
            }

            frame.Add(block);
        }

        return frames
            .Select(f => f.OrderBy(i => i.Area).ThenBy(i => i.Offset).ToImmutableArray())
            .OrderBy(f => f[0].Area).ThenBy(f => f[0].Offset)
            .ToList();
    }
}
