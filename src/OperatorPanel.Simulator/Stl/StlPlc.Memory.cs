using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Simulator.Stl;

/// <summary>Operand access: big-endian bytes, words and double words (VW100 = VB100 high byte), bits, accumulators and pointers.</summary>
public sealed partial class StlPlc
{
    private static uint Mask(int bytes) => bytes switch
    {
        1 => 0xFFu,
        2 => 0xFFFFu,
        _ => 0xFFFF_FFFFu,
    };

    private static uint ReadBytes(byte[] area, int offset, int bytes) => bytes switch
    {
        1 => area[offset],
        2 => (uint)((area[offset] << 8) | area[offset + 1]),
        _ => (uint)((area[offset] << 24) | (area[offset + 1] << 16) | (area[offset + 2] << 8) | area[offset + 3]),
    };

    private static void WriteBytes(byte[] area, int offset, int bytes, uint value)
    {
        for (var i = bytes - 1; i >= 0; i--)
        {
            area[offset + i] = (byte)value;
            value >>= 8;
        }
    }

    private uint Read(StlLoc loc, int bytes) => loc.Kind switch
    {
        StlLocKind.Constant => loc.Value & Mask(bytes),
        StlLocKind.Direct => ReadBytes(_areas[loc.Area], loc.Offset, bytes),
        StlLocKind.Local => ReadBytes(_l, _lBase + loc.Offset, bytes),
        StlLocKind.Accumulator => _ac[loc.Offset] & Mask(bytes),
        StlLocKind.Timer => (ushort)TimerValue(loc.Offset) & Mask(bytes),
        StlLocKind.Counter => (ushort)_counters[loc.Offset].Value & Mask(bytes),
        StlLocKind.Indirect => TryPointer(loc, bytes, out var area, out var offset) ? ReadBytes(area, offset, bytes) : 0,
    };

    /// <summary>
    /// A byte or word written to an accumulator replaces its low byte or word (C233 p. 5-10: byte and word access uses
    /// the least significant 8 or 16 bits); that the upper bytes are kept is unconfirmed, no page says.
    /// </summary>
    private void Write(StlLoc loc, int bytes, uint value)
    {
        switch (loc.Kind)
        {
            case StlLocKind.Direct:
                WriteBytes(_areas[loc.Area], loc.Offset, bytes, value);
                break;
            case StlLocKind.Local:
                WriteBytes(_l, _lBase + loc.Offset, bytes, value);
                break;
            case StlLocKind.Accumulator:
                _ac[loc.Offset] = (_ac[loc.Offset] & ~Mask(bytes)) | (value & Mask(bytes));
                break;
            case StlLocKind.Timer:
                SetTimerValue(loc.Offset, (short)value);
                break;
            case StlLocKind.Counter:
                _counters[loc.Offset].Value = (short)value;
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

    private bool ReadBit(StlLoc loc) => loc.Kind switch
    {
        StlLocKind.Local => ((_l[_lBase + loc.Offset] >> loc.Bit) & 1) != 0,
        StlLocKind.Timer => TimerBit(loc.Offset),
        StlLocKind.Counter => _counters[loc.Offset].Bit,
        StlLocKind.Constant or StlLocKind.Direct or StlLocKind.Accumulator or StlLocKind.Indirect =>
            ((_areas[loc.Area][loc.Offset] >> loc.Bit) & 1) != 0,
    };

    private void WriteBit(StlLoc loc, bool value)
    {
        if (loc.Kind is StlLocKind.Timer or StlLocKind.Counter)
        {
            WriteTimerOrCounterBit(loc, value);
            return;
        }

        var (area, offset) = loc.Kind == StlLocKind.Local ? (_l, _lBase + loc.Offset) : (_areas[loc.Area], loc.Offset);
        area[offset] = value ? (byte)(area[offset] | (1 << loc.Bit)) : (byte)(area[offset] & ~(1 << loc.Bit));
    }

    /// <summary>S/R N: N consecutive bits from the operand on, across byte boundaries, stopping at the end of the area.</summary>
    private void WriteBits(StlLoc loc, int count, bool value)
    {
        if (loc.Kind is StlLocKind.Timer or StlLocKind.Counter)
        {
            for (var n = loc.Offset; n < loc.Offset + count && n <= 255; n++)
            {
                WriteTimerOrCounterBit(new StlLoc { Kind = loc.Kind, Offset = n }, value);
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
    private bool TrySpan(StlLoc loc, int bytes, out byte[] area, out int offset)
    {
        (area, offset) = loc.Kind switch
        {
            StlLocKind.Direct => (_areas[loc.Area], loc.Offset),
            StlLocKind.Local => (_l, _lBase + loc.Offset),
            StlLocKind.Constant or StlLocKind.Accumulator or StlLocKind.Indirect or StlLocKind.Timer or StlLocKind.Counter =>
                (Array.Empty<byte>(), 0),
        };
        if (loc.Kind == StlLocKind.Indirect)
        {
            return TryPointer(loc, bytes, out area, out offset);
        }

        var end = loc.Kind == StlLocKind.Local ? _lBase + LBytes : area.Length;
        return offset + bytes <= end || Failed("OperandRange", $"{bytes} bytes from the operand run past the end of its area");
    }

    private bool TryPointer(StlLoc loc, int bytes, out byte[] area, out int offset)
    {
        var pointer = Read(loc.Holder!, 4);
        var (areaIndex, target) = StlPointer.Decode(pointer);
        var valid = areaIndex is (int)MemoryArea.I or (int)MemoryArea.Q or (int)MemoryArea.M or (int)MemoryArea.V
            or (int)MemoryArea.SM or (int)MemoryArea.S;
        area = valid ? _areas[areaIndex] : [];
        offset = target;
        return (valid && target + bytes <= area.Length)
            || Failed("IndirectAddress", $"pointer 16#{pointer:X8} does not address {bytes} byte(s) inside I, Q, M, V, SM or S");
    }

    private bool Failed(string code, string message)
    {
        if (Fault is null && _op is not null)
        {
            Fault = new StlFault(code, message, _frames[Math.Max(_depth, 0)].Block?.Name ?? "?", _op.Line);
        }

        return false;
    }
}
