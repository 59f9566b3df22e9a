using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Core.Polling;

/// <summary>
/// One exchange of a poll cycle: up to 20 blocks of one station, read in item order. With a <see cref="List"/> id the
/// blocks are stored in the station once (DEFINE LIST) and polled with READ CHANGES; without one, by a plain READ.
/// </summary>
public sealed record PollFrame(Station Station, ImmutableArray<ReadItem> Items)
{
    /// <summary>The list id 1-4 the frame is stored under, in definition order; null for a plain READ.</summary>
    public int? List { get; init; }

    /// <summary>Bytes in the reply: the lengths of all items.</summary>
    public int DataBytes => Items.Sum(i => i.Length);
}
