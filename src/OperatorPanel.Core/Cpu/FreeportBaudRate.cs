namespace OperatorPanel.Core.Cpu;

/// <summary>A Freeport baud rate and its 3-bit code in SMB30/SMB130 bits 2-4 (seed 002, Table C-11).</summary>
public readonly record struct FreeportBaudRate(int Baud, int Code);
