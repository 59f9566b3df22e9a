namespace OperatorPanel.Core.Addressing;

/// <summary>A refused address: what was wrong, in a sentence a technician can act on.</summary>
public sealed record AddressError(AddressErrorKind Kind, string Message)
{
    public override string ToString() => Message;
}
