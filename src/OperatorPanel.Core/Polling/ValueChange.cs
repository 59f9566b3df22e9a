using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Core.Polling;

/// <summary>One address whose value or quality changed; published to subscribers in a batch per cycle or write.</summary>
public sealed record ValueChange(Station Station, PlcAddress Address, PolledValue Previous, PolledValue Current);
