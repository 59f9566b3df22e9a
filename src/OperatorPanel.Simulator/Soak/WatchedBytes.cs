using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Simulator.Soak;

/// <summary>Bytes <paramref name="First"/>..First+Count-1 of one area that only panel writes may change.</summary>
public readonly record struct WatchedBytes(ProtocolArea Area, int First, int Count);
