namespace OperatorPanel.Core.Ppi.S7;

/// <summary>
/// The address of one read or write item: 12 bytes on the wire, 16#12 16#0A 16#10 TS COUNT(2) DB(2) AREA ADDRESS(3)
/// (libnodave doc/pdu.html "Forming the item address"; docs/ppi.md section 5). <see cref="Address"/> is a bit address
/// (byte x 8 + bit) for every area but timers and counters, where it is the timer or counter number.
/// </summary>
public readonly record struct S7Item(S7TransportSize Size, int Count, int DataBlock, S7Area Area, int Address)
{
    /// <summary>Bytes of one item address in a request's parameters.</summary>
    public const int EncodedLength = 12;

    /// <summary>Data bytes per timer or counter in a read answer: a status byte and a 4-byte value (captures, docs/ppi.md section 6).</summary>
    public const int TimerCounterBytes = 5;

    /// <summary>The byte number the item starts at (the element number for timers and counters).</summary>
    public int ByteOffset => IsTimerOrCounter ? Address : Address / 8;

    public int BitNumber => IsTimerOrCounter ? 0 : Address % 8;

    public bool IsTimerOrCounter => Size is S7TransportSize.Timer or S7TransportSize.Counter;

    /// <summary>Data bytes the item reads or writes: one per bit item, 2 per word, 5 per timer or counter.</summary>
    public int DataLength => Size switch
    {
        S7TransportSize.Bit => Count,
        S7TransportSize.Word => 2 * Count,
        S7TransportSize.Timer or S7TransportSize.Counter => TimerCounterBytes * Count,
        _ => Count,
    };

    /// <summary><paramref name="count"/> bytes from <paramref name="byteOffset"/>; V is data block 1, every other area block 0.</summary>
    public static S7Item Bytes(S7Area area, int byteOffset, int count) =>
        Create(S7TransportSize.Byte, count, area, byteOffset * 8);

    public static S7Item Bit(S7Area area, int byteOffset, int bit)
    {
        ArgumentOutOfRangeException.ThrowIfNegative(bit);
        ArgumentOutOfRangeException.ThrowIfGreaterThan(bit, 7);
        return Create(S7TransportSize.Bit, 1, area, (byteOffset * 8) + bit);
    }

    /// <summary><paramref name="count"/> words from <paramref name="byteOffset"/>: how AIW and AQW are read and written.</summary>
    public static S7Item Words(S7Area area, int byteOffset, int count) =>
        Create(S7TransportSize.Word, count, area, byteOffset * 8);

    public static S7Item Timers(int first, int count) => Create(S7TransportSize.Timer, count, S7Area.T, first);

    public static S7Item Counters(int first, int count) => Create(S7TransportSize.Counter, count, S7Area.C, first);

    public override string ToString() => IsTimerOrCounter
        ? $"{Area}{Address} x{Count}"
        : Size == S7TransportSize.Bit ? $"{Area}{ByteOffset}.{BitNumber}" : $"{Area} byte {ByteOffset} {Size} x{Count}";

    private static S7Item Create(S7TransportSize size, int count, S7Area area, int address)
    {
        ArgumentOutOfRangeException.ThrowIfNegative(address);
        ArgumentOutOfRangeException.ThrowIfGreaterThan(address, 0xFFFFFF);
        ArgumentOutOfRangeException.ThrowIfLessThan(count, 1);
        ArgumentOutOfRangeException.ThrowIfGreaterThan(count, ushort.MaxValue);
        return new S7Item(size, count, area == S7Area.V ? 1 : 0, area, address);
    }
}
