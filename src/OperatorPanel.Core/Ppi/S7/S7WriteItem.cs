using System.Collections.Immutable;

namespace OperatorPanel.Core.Ppi.S7;

/// <summary>An item to write and its bytes (one byte, 0 or 1, for a bit item).</summary>
public sealed record S7WriteItem(S7Item Item, ImmutableArray<byte> Data)
{
    /// <summary>The data item's size byte: 16#03 for a bit, 16#04 (length in bits) otherwise (libnodave daveAddVarToWriteRequest).</summary>
    public S7DataSize DataSize => Item.Size == S7TransportSize.Bit ? S7DataSize.Bit : S7DataSize.Bits;

    public static S7WriteItem Of(S7Item item, ReadOnlySpan<byte> data)
    {
        if (data.Length != item.DataLength)
        {
            throw new ArgumentException($"{item} takes {item.DataLength} bytes, not {data.Length}", nameof(data));
        }

        return new S7WriteItem(item, [.. data]);
    }
}
