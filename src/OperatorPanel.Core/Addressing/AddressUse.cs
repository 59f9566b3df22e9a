namespace OperatorPanel.Core.Addressing;

/// <summary>What the panel means to do with an address.</summary>
public enum AddressUse
{
    Read,
    Write,
}
