using System.Globalization;

namespace OperatorPanel.Core.Addressing;

/// <summary>
/// A direct S7-200 address such as <c>I0.3</c>, <c>VB100</c>, <c>VW200</c>, <c>VD300</c>, <c>SMB30</c>, <c>AIW0</c> or
/// <c>T37</c> (a timer's or counter's current value: one word, numbered rather than placed at a byte).
/// Immutable; <see cref="ToString"/> prints the canonical form that <see cref="TryParse(string?, out PlcAddress, out AddressError?)"/> reads back.
/// </summary>
public readonly partial record struct PlcAddress
{
    /// <summary>Largest byte number the parser accepts; every S7-200 area is far smaller (V tops out at VB10239).</summary>
    public const int MaxByteOffset = 65535;

    private PlcAddress(MemoryArea area, int byteOffset, int? bit, AccessWidth width)
    {
        Area = area;
        ByteOffset = byteOffset;
        Bit = bit;
        Width = width;
    }

    public MemoryArea Area { get; }

    /// <summary>Number of the first byte, counted from byte 0 of <see cref="Area"/>; for a timer or counter its number (T37: 37).</summary>
    public int ByteOffset { get; }

    /// <summary>Bit 0-7 within the byte for a bit address; null otherwise.</summary>
    public int? Bit { get; }

    public AccessWidth Width { get; }

    /// <summary>Number of the last byte the access touches (a double word at VD300 ends at VB303).</summary>
    public int LastByte => ByteOffset + Width.ByteCount() - 1;

    public static PlcAddress ForBit(MemoryArea area, int byteOffset, int bit)
    {
        ArgumentOutOfRangeException.ThrowIfNegative(byteOffset);
        ArgumentOutOfRangeException.ThrowIfGreaterThan(byteOffset, MaxByteOffset);
        ArgumentOutOfRangeException.ThrowIfNegative(bit);
        ArgumentOutOfRangeException.ThrowIfGreaterThan(bit, 7);
        if (!AreaSyntax.HasBits(area))
        {
            throw new ArgumentException($"{area} has no bit addresses", nameof(area));
        }

        return new PlcAddress(area, byteOffset, bit, AccessWidth.Bit);
    }

    public static PlcAddress ForBytes(MemoryArea area, int byteOffset, AccessWidth width)
    {
        ArgumentOutOfRangeException.ThrowIfNegative(byteOffset);
        ArgumentOutOfRangeException.ThrowIfGreaterThan(byteOffset, MaxByteOffset);
        if (width == AccessWidth.Bit)
        {
            throw new ArgumentException("use ForBit for bit addresses", nameof(width));
        }

        if (!AreaSyntax.Allows(area, width))
        {
            throw new ArgumentException($"{area} has no {width} addresses", nameof(width));
        }

        return new PlcAddress(area, byteOffset, null, width);
    }

    /// <summary>Parses an address; throws <see cref="FormatException"/> with the reason. Prefer TryParse for user text.</summary>
    public static PlcAddress Parse(string text) =>
        TryParse(text, out var address, out var error) ? address : throw new FormatException(error!.Message);

    public override string ToString()
    {
        var area = AreaSyntax.Prefix(Area);
        if (AreaSyntax.IsNumbered(Area))
        {
            return string.Create(CultureInfo.InvariantCulture, $"{area}{ByteOffset}");
        }

        return Width == AccessWidth.Bit
            ? string.Create(CultureInfo.InvariantCulture, $"{area}{ByteOffset}.{Bit}")
            : string.Create(CultureInfo.InvariantCulture, $"{area}{Width.Letter()}{ByteOffset}");
    }
}
