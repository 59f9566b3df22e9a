namespace OperatorPanel.Core.Transport;

/// <summary>Parity of a Freeport character (SMB30/SMB130 bits 6-7: 00 none, 01 even, 11 odd; seed 002 Table C-11).</summary>
public enum Parity
{
    None,
    Even,
    Odd,
}
