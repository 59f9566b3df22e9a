using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Core.Polling;

/// <summary>Finds the reply bytes that carry a span, byte by byte, and joins neighbours into slices.</summary>
internal static class SliceLocator
{
    public static ImmutableArray<ReplySlice> Locate(ImmutableArray<PollFrame> frames, Station station, ReadItem span)
    {
        var slices = new List<ReplySlice>();
        for (var address = span.Offset; address < span.Offset + span.Length; address++)
        {
            var (frame, dataOffset) = Find(frames, station, span.Area, address);
            if (slices.Count > 0 && slices[^1].FrameIndex == frame && slices[^1].DataOffset + slices[^1].Length == dataOffset)
            {
                slices[^1] = slices[^1] with { Length = slices[^1].Length + 1 };
            }
            else
            {
                slices.Add(new ReplySlice(frame, dataOffset, 1));
            }
        }

        return [.. slices];
    }

    private static (int Frame, int DataOffset) Find(ImmutableArray<PollFrame> frames, Station station, ProtocolArea area, int address)
    {
        for (var f = 0; f < frames.Length; f++)
        {
            if (frames[f].Station != station)
            {
                continue;
            }

            var dataOffset = 0;
            foreach (var item in frames[f].Items)
            {
                if (item.Area == area && address >= item.Offset && address < item.Offset + item.Length)
                {
                    return (f, dataOffset + address - item.Offset);
                }

                dataOffset += item.Length;
            }
        }

        throw new InvalidOperationException($"{station} {area} byte {address} is in no frame of the plan");
    }
}
