using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Ppi.S7;

namespace OperatorPanel.Simulator.Stl.Ppi;

/// <summary>
/// The simulated CPU's memory as PPI reaches it (docs/ppi.md sections 6 and 11). Return codes where a real S7-200's
/// is not published are the conservative ones libnodave describes for the 200 family: 16#03 for what does not exist or
/// may not be done (a data block other than 1, a bit item of more than one bit, writing SMB0-SMB29 or AIW, timers and
/// counters written), 16#05 beyond an area's end, 16#07 for data that does not fit its item.
/// </summary>
public sealed class StlPpiMemory(StlPlc plc) : IPpiMemory
{
    /// <summary>Timer and counter status byte bit for the T/C bit, as two captures suggest (16#02; unconfirmed).</summary>
    public const byte TimerCounterBitFlag = 0x02;

    public S7ItemResult Read(S7Item item)
    {
        if (item.IsTimerOrCounter)
        {
            return ReadTimersOrCounters(item);
        }

        if (!TryBytes(item, out var bytes, out var offset, out var length, out var code))
        {
            return S7ItemResult.Failed(code);
        }

        if (item.Size == S7TransportSize.Bit)
        {
            return S7ItemResult.Of(S7DataSize.Bit, [(byte)((bytes[offset] >> item.BitNumber) & 1)]);
        }

        return S7ItemResult.Of(S7DataSize.Bits, bytes.AsSpan(offset, length));
    }

    public S7ReturnCode Write(S7WriteItem item)
    {
        ArgumentNullException.ThrowIfNull(item);
        var address = item.Item;
        if (address.IsTimerOrCounter || address.Area == S7Area.AI
            || (address.Area == S7Area.SM && address.ByteOffset < plc.Cpu.ReadOnlySmBytes))
        {
            return S7ReturnCode.AccessDenied;
        }

        if (!TryBytes(address, out var bytes, out var offset, out var length, out var code))
        {
            return code;
        }

        if (address.Size == S7TransportSize.Bit)
        {
            var mask = (byte)(1 << address.BitNumber);
            bytes[offset] = (byte)((item.Data[0] & 1) != 0 ? bytes[offset] | mask : bytes[offset] & ~mask);
        }
        else
        {
            item.Data.AsSpan(0, length).CopyTo(bytes.AsSpan(offset));
        }

        return S7ReturnCode.Success;
    }

    public bool Control(S7Function function)
    {
        if (function == S7Function.PlcStop)
        {
            plc.Stop();
            return true;
        }

        plc.Run();
        return plc.Mode == Reference.OperatingMode.Run;
    }

    private bool TryBytes(S7Item item, out byte[] bytes, out int offset, out int length, out S7ReturnCode code)
    {
        (bytes, offset, length) = ([], item.ByteOffset, item.DataLength);
        code = item switch
        {
            { Area: S7Area.V, DataBlock: not 1 } => S7ReturnCode.AccessDenied,
            { Size: S7TransportSize.Bit, Count: not 1 } => S7ReturnCode.AccessDenied,
            _ when Area(item.Area) is not { } area => S7ReturnCode.AccessDenied,
            _ => S7ReturnCode.Success,
        };
        if (code != S7ReturnCode.Success)
        {
            return false;
        }

        bytes = plc.AreaBytes(Area(item.Area)!.Value);
        code = offset + length <= bytes.Length ? S7ReturnCode.Success : S7ReturnCode.AddressOutOfRange;
        return code == S7ReturnCode.Success;
    }

    private static MemoryArea? Area(S7Area area) => area switch
    {
        S7Area.I => MemoryArea.I,
        S7Area.Q => MemoryArea.Q,
        S7Area.M => MemoryArea.M,
        S7Area.V => MemoryArea.V,
        S7Area.SM => MemoryArea.SM,
        S7Area.S => MemoryArea.S,
        S7Area.AI => MemoryArea.AI,
        S7Area.AQ => MemoryArea.AQ,
        _ => null,
    };

    /// <summary>5 bytes each: a status byte and the current value as a 4-byte big-endian number (captures, docs/ppi.md section 6).</summary>
    private S7ItemResult ReadTimersOrCounters(S7Item item)
    {
        var timers = item.Area == S7Area.T && item.Size == S7TransportSize.Timer;
        var counters = item.Area == S7Area.C && item.Size == S7TransportSize.Counter;
        var limit = timers ? plc.Cpu.Timers : plc.Cpu.Counters;
        if (!timers && !counters)
        {
            return S7ItemResult.Failed(S7ReturnCode.AccessDenied);
        }

        if (item.Address + item.Count > limit)
        {
            return S7ItemResult.Failed(S7ReturnCode.AddressOutOfRange);
        }

        var data = new byte[item.DataLength];
        for (var i = 0; i < item.Count; i++)
        {
            var number = item.Address + i;
            var (value, bit) = timers
                ? (plc.TimerCurrentValue(number), plc.TimerBitValue(number))
                : (plc.CounterCurrentValue(number), plc.CounterBitValue(number));
            var at = i * S7Item.TimerCounterBytes;
            data[at] = bit ? TimerCounterBitFlag : (byte)0;
            var sign = value < 0 ? (byte)0xFF : (byte)0;
            (data[at + 1], data[at + 2], data[at + 3], data[at + 4]) = (sign, sign, (byte)(value >> 8), (byte)value);
        }

        return S7ItemResult.Of(S7DataSize.OctetString, data);
    }
}
