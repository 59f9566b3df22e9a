using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Core.Polling;

/// <summary>One address the panel keeps up to date: an input, an output, a memory cell or an alarm bit.</summary>
public readonly record struct WatchedItem(Station Station, PlcAddress Address)
{
    public override string ToString() => $"{Station} {Address}";
}
