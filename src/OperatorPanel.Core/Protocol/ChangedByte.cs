namespace OperatorPanel.Core.Protocol;

/// <summary>One INDEX VALUE pair of a READ CHANGES reply: byte <paramref name="Index"/> of the list's data is now <paramref name="Value"/>.</summary>
public readonly record struct ChangedByte(byte Index, byte Value);
