using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Simulator.Stl.Execution;

/// <summary>
/// Operand access: big-endian bytes, words and double words (VW100 = VB100 high byte), bits, L memory of the running
/// level, accumulators, timer and counter values, pointers; and SMB1, the instruction status bits.
/// </summary>
internal sealed partial class StlMachine
{
    /// <summary>SMB1 (seed 002, Table C-2): SM1.0 zero, SM1.1 overflow, SM1.2 negative, SM1.3 division by zero, ...</summary>
    public ref byte Flags => ref Memory.SM[1];

    public static uint Mask(int bytes) => bytes switch
    {
        1 => 0xFFu,
        2 => 0xFFFFu,
        _ => 0xFFFF_FFFFu,
    };

    public static uint ReadBytes(byte[] area, int offset, int bytes) => bytes switch
    {
        1 => area[offset],
        2 => (uint)((area[offset] << 8) | area[offset + 1]),
        _ => (uint)((area[offset] << 24) | (area[offset + 1] << 16) | (area[offset + 2] << 8) | area[offset + 3]),
    };

    public static void WriteBytes(byte[] area, int offset, int bytes, uint value)
    {
        for (var i = bytes - 1; i >= 0; i--)
        {
            area[offset + i] = (byte)value;
            value >>= 8;
        }
    }

    /// <summary>Sets the SMB1 bits of <paramref name="mask"/> to <paramref name="value"/>, the others unchanged.</summary>
    public void SetFlags(byte mask, byte value) => Flags = (byte)((Flags & ~mask) | value);

    public uint Read(StlLoc loc, int bytes) => loc.Kind switch
    {
        StlLocKind.Constant => loc.Value & Mask(bytes),
        StlLocKind.Direct => ReadBytes(_areas[loc.Area], loc.Offset, bytes),
        StlLocKind.Local => ReadBytes(_l, Calls.LBase + loc.Offset, bytes),
        StlLocKind.Accumulator => _ac[loc.Offset] & Mask(bytes),
        StlLocKind.Timer => (ushort)Timers.Value(loc.Offset) & Mask(bytes),
        StlLocKind.Counter => (ushort)Counters.Value(loc.Offset) & Mask(bytes),
        StlLocKind.Indirect => TryPointer(loc, bytes, out var area, out var offset) ? ReadBytes(area, offset, bytes) : 0,
    };

    public float ReadReal(StlLoc loc) => BitConverter.UInt32BitsToSingle(Read(loc, 4));

    /// <summary>
    /// A byte or word written to an accumulator replaces its low byte or word (C233 p. 5-10: byte and word access uses
    /// the least significant 8 or 16 bits); that the upper bytes are kept is unconfirmed, no page says.
    /// </summary>
    public void Write(StlLoc loc, int bytes, uint value)
    {
        switch (loc.Kind)
        {
            case StlLocKind.Direct:
                WriteBytes(_areas[loc.Area], loc.Offset, bytes, value);
                break;
            case StlLocKind.Local:
                WriteBytes(_l, Calls.LBase + loc.Offset, bytes, value);
                break;
            case StlLocKind.Accumulator:
                _ac[loc.Offset] = (_ac[loc.Offset] & ~Mask(bytes)) | (value & Mask(bytes));
                break;
            case StlLocKind.Timer:
                Timers.SetValue(loc.Offset, (short)value);
                break;
            case StlLocKind.Counter:
                Counters.SetValue(loc.Offset, (short)value);
                break;
            case StlLocKind.Indirect:
                if (TryPointer(loc, bytes, out var area, out var offset))
                {
                    WriteBytes(area, offset, bytes, value);
                }

                break;
            case StlLocKind.Constant:
                throw new InvalidOperationException("the loader lets no constant be written");
        }
    }

    public bool ReadBit(StlLoc loc) => loc.Kind switch
    {
        StlLocKind.Local => ((_l[Calls.LBase + loc.Offset] >> loc.Bit) & 1) != 0,
        StlLocKind.Timer => Timers.Bit(loc.Offset),
        StlLocKind.Counter => Counters.Bit(loc.Offset),
        StlLocKind.Constant or StlLocKind.Direct or StlLocKind.Accumulator or StlLocKind.Indirect =>
            ((_areas[loc.Area][loc.Offset] >> loc.Bit) & 1) != 0,
    };

    /// <summary>A bit; S Tn/Cn sets the bit only, R Tn/Cn clears bit and value (and stops a timer).</summary>
    public void WriteBit(StlLoc loc, bool value)
    {
        switch (loc.Kind)
        {
            case StlLocKind.Timer when value:
                Timers.SetBit(loc.Offset);
                return;
            case StlLocKind.Timer:
                Timers.Reset(loc.Offset);
                return;
            case StlLocKind.Counter:
                Counters.WriteBit(loc.Offset, value);
                return;
        }

        var (area, offset) = loc.Kind == StlLocKind.Local ? (_l, Calls.LBase + loc.Offset) : (_areas[loc.Area], loc.Offset);
        area[offset] = value ? (byte)(area[offset] | (1 << loc.Bit)) : (byte)(area[offset] & ~(1 << loc.Bit));
    }

    /// <summary>S/R N: N consecutive bits from the operand on, across byte boundaries, stopping at the end of the area.</summary>
    public void WriteBits(StlLoc loc, int count, bool value)
    {
        if (loc.Kind is StlLocKind.Timer or StlLocKind.Counter)
        {
            for (var n = loc.Offset; n < loc.Offset + count && n <= 255; n++)
            {
                WriteBit(new StlLoc { Kind = loc.Kind, Offset = n }, value);
            }

            return;
        }

        var length = loc.Kind == StlLocKind.Local ? LBytes : _areas[loc.Area].Length;
        var first = (loc.Offset * 8) + loc.Bit;
        for (var n = first; n < first + count && n < length * 8; n++)
        {
            WriteBit(new StlLoc { Kind = loc.Kind, Area = loc.Area, Offset = n / 8, Bit = n % 8 }, value);
        }
    }

    /// <summary>The bytes a block operand (BMB, ATH, RCV buffer) starts at, with <paramref name="bytes"/> of them inside the area.</summary>
    public bool TrySpan(StlLoc loc, int bytes, out byte[] area, out int offset)
    {
        (area, offset) = loc.Kind switch
        {
            StlLocKind.Direct => (_areas[loc.Area], loc.Offset),
            StlLocKind.Local => (_l, Calls.LBase + loc.Offset),
            StlLocKind.Constant or StlLocKind.Accumulator or StlLocKind.Indirect or StlLocKind.Timer or StlLocKind.Counter =>
                (Array.Empty<byte>(), 0),
        };
        if (loc.Kind == StlLocKind.Indirect)
        {
            return TryPointer(loc, bytes, out area, out offset);
        }

        var end = loc.Kind == StlLocKind.Local ? Calls.LBase + LBytes : area.Length;
        return offset + bytes <= end || Fail("OperandRange", $"{bytes} bytes from the operand run past the end of its area");
    }

    /// <summary>How many bits the area of a bit operand has (the running level's 64 bytes for L).</summary>
    public int BitLimit(StlLoc loc) => (loc.Kind == StlLocKind.Local ? LBytes : _areas[loc.Area].Length) * 8;

    private bool TryPointer(StlLoc loc, int bytes, out byte[] area, out int offset)
    {
        var pointer = Read(loc.Holder!, 4);
        var (areaIndex, target) = StlPointer.Decode(pointer);
        var valid = areaIndex is (int)MemoryArea.I or (int)MemoryArea.Q or (int)MemoryArea.M or (int)MemoryArea.V
            or (int)MemoryArea.SM or (int)MemoryArea.S;
        area = valid ? _areas[areaIndex] : [];
        offset = target;
        return (valid && target + bytes <= area.Length)
            || Fail("IndirectAddress", $"pointer 16#{pointer:X8} does not address {bytes} byte(s) inside I, Q, M, V, SM or S");
    }
}
