using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Core.Polling;

/// <summary>One READ exchange of a poll cycle: up to 20 blocks of one station, read in item order.</summary>
public sealed record PollFrame(Station Station, ImmutableArray<ReadItem> Items)
{
    /// <summary>Bytes in the reply: the lengths of all items.</summary>
    public int DataBytes => Items.Sum(i => i.Length);
}
