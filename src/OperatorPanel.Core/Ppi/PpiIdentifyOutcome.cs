namespace OperatorPanel.Core.Ppi;

/// <summary>What a PPI identify brought: the identity, or why there is none (the station silent, an item refused).</summary>
public sealed record PpiIdentifyOutcome(PpiIdentity? Identity, string? Error);
