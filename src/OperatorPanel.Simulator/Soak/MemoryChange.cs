using System.Collections.Immutable;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Simulator.Soak;

/// <summary>
/// One write the simulated PLC executed, seen as the bytes it changed: <see cref="Before"/> and <see cref="After"/>
/// cover <see cref="First"/> to the last changed byte (bytes between that kept their value are included, equal).
/// <see cref="Timestamp"/> (TimeProvider ticks) is taken when the change was seen, after the step that made it and
/// before any reply that step produced leaves the host.
/// </summary>
public sealed record MemoryChange(long Timestamp, ProtocolArea Area, int First, ImmutableArray<byte> Before, ImmutableArray<byte> After)
{
    public int Last => First + After.Length - 1;
}
