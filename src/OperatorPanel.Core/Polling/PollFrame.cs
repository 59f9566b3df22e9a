using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Ppi.S7;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Core.Polling;

/// <summary>
/// One exchange of a poll cycle: up to 20 blocks of one station, read in item order. With a <see cref="List"/> id the
/// blocks are stored in the station once (DEFINE LIST) and polled with READ CHANGES; without one, by a plain READ.
/// On a PPI bus a frame is one S7 item instead (<see cref="PpiItem"/>, <see cref="PpiPollPlanner"/>) and has no
/// Freeport blocks: the S7 item reaches the areas the handler's protocol has no code for (S, AI, AQ, T, C).
/// </summary>
public sealed record PollFrame(Station Station, ImmutableArray<ReadItem> Items)
{
    /// <summary>The list id 1-4 the frame is stored under, in definition order; null for a plain READ.</summary>
    public int? List { get; init; }

    /// <summary>The S7 item of a PPI bus's frame; null on a Freeport bus.</summary>
    public S7Item? PpiItem { get; init; }

    /// <summary>Bytes in the reply: the lengths of all items (the S7 item's answer on a PPI bus).</summary>
    public int DataBytes => PpiItem?.DataLength ?? Items.Sum(i => i.Length);

    /// <summary>A PPI bus's frame: one S7 item of <paramref name="station"/>.</summary>
    public static PollFrame ForPpi(Station station, S7Item item) => new(station, []) { PpiItem = item };
}
