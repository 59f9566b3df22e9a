using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Writes;

namespace OperatorPanel.Simulator.Soak;

/// <summary>
/// The panel's <paramref name="Number"/>-th write (from 1): <paramref name="Address"/> := <paramref name="Value"/> (its
/// bytes, or 00/01 for a bit), handed to the bus at <paramref name="Sent"/> and reported as <paramref name="Outcome"/>
/// at <paramref name="Reported"/> (TimeProvider ticks). The soak has one write in flight at a time, so the write in
/// flight at any moment is known.
/// </summary>
public sealed record SoakWrite(int Number, PlcAddress Address, ImmutableArray<byte> Value, long Sent, long Reported, WriteOutcome Outcome);
