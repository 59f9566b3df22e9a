using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Core.Writes;

/// <summary>
/// A value the operator wants in the PLC. A bit becomes a WRITE BIT (set or reset on the PLC itself, atomic with
/// respect to the PLC program); a byte, word or double word becomes a WRITE of its bytes, big-endian as the S7-200
/// stores them (VW100 = VB100 high byte, VB101 low byte).
/// </summary>
public sealed record WriteRequest
{
    private WriteRequest(Station station, PlcAddress address, ImmutableArray<byte> data, bool? bitValue)
    {
        Station = station;
        Address = address;
        Data = data;
        BitValue = bitValue;
    }

    public Station Station { get; }

    public PlcAddress Address { get; }

    /// <summary>The bytes to write; empty for a bit.</summary>
    public ImmutableArray<byte> Data { get; }

    /// <summary>The bit to set (true) or reset (false); null for a byte, word or double word.</summary>
    public bool? BitValue { get; }

    /// <summary>The address's symbol in the project ("FillSetpoint"), for the write's record; null when none is known.</summary>
    public string? Symbol { get; init; }

    /// <summary>The new value as <see cref="Polling.PolledValue.Raw"/> holds it: the bytes, or 00/01 for a bit.</summary>
    public ImmutableArray<byte> Value => BitValue is { } bit ? [bit ? (byte)1 : (byte)0] : Data;

    /// <summary>A byte, word or double word; <paramref name="data"/> must have exactly the address's width.</summary>
    public static WriteRequest Bytes(Station station, PlcAddress address, ImmutableArray<byte> data)
    {
        if (address.Width == AccessWidth.Bit)
        {
            throw new ArgumentException($"{address} is a bit: use WriteRequest.Bit", nameof(address));
        }

        if (data.IsDefault || data.Length != address.Width.ByteCount())
        {
            throw new ArgumentException($"{address} takes {address.Width.ByteCount()} bytes", nameof(data));
        }

        return new WriteRequest(station, address, data, null);
    }

    public static WriteRequest Bit(Station station, PlcAddress address, bool value)
    {
        if (address.Width != AccessWidth.Bit)
        {
            throw new ArgumentException($"{address} is not a bit: use WriteRequest.Bytes", nameof(address));
        }

        return new WriteRequest(station, address, [], value);
    }

    public override string ToString() => $"{Station} {Address} := {WriteLog.Format(Address, Value)}";
}
