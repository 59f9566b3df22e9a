using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Simulator.Soak;

/// <summary>
/// <paramref name="Address"/> shown as good with <paramref name="Value"/> (its bytes, or 00/01 for a bit, as the
/// panel's values hold it): it must be a value the PLC held there at some moment from <paramref name="From"/> (the start
/// of the step before, which may have set it by a write's read-back) to <paramref name="Until"/> (when it was shown),
/// both TimeProvider ticks.
/// </summary>
public readonly record struct ShownValue(PlcAddress Address, ImmutableArray<byte> Value, long From, long Until);
