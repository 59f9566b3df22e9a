namespace OperatorPanel.Core.Ppi.S7;

/// <summary>How a data item's length counts, by its <see cref="S7DataSize"/>.</summary>
public static class S7DataSizes
{
    /// <summary>Data bytes a data item of <paramref name="size"/> and <paramref name="length"/> carries; -1 for an unknown size.</summary>
    public static int ByteCount(S7DataSize size, int length) => size switch
    {
        S7DataSize.Bits or S7DataSize.Integer => (length + 7) / 8,
        S7DataSize.Bit or S7DataSize.DoubleInteger or S7DataSize.Real or S7DataSize.OctetString => length,
        _ => -1,
    };
}
