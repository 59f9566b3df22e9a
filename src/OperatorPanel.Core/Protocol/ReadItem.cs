namespace OperatorPanel.Core.Protocol;

/// <summary>One block of a READ request: <paramref name="Length"/> bytes from <paramref name="Offset"/> of <paramref name="Area"/>.</summary>
public readonly record struct ReadItem(ProtocolArea Area, int Offset, int Length);
