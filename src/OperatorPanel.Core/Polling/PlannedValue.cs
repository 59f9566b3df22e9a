using System.Collections.Immutable;

namespace OperatorPanel.Core.Polling;

/// <summary>A watched item and the reply bytes that carry it, in address order.</summary>
public sealed record PlannedValue(WatchedItem Item, ImmutableArray<ReplySlice> Slices);
