using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Simulator.Reference;

/// <summary>
/// The byte areas the protocol reaches, sized from the CPU profile (I 16, Q 16, M 32, V and SM per CPU).
/// Words and double words are big-endian, as in the S7-200 (VW100 = VB100 high byte, VB101 low byte).
/// </summary>
public sealed class PlcMemory
{
    public PlcMemory(CpuProfile cpu)
    {
        ArgumentNullException.ThrowIfNull(cpu);
        I = Allocate(cpu, MemoryArea.I);
        Q = Allocate(cpu, MemoryArea.Q);
        M = Allocate(cpu, MemoryArea.M);
        V = Allocate(cpu, MemoryArea.V);
        SM = Allocate(cpu, MemoryArea.SM);
    }

    public byte[] I { get; }

    public byte[] Q { get; }

    public byte[] M { get; }

    public byte[] V { get; }

    public byte[] SM { get; }

    public byte[] Area(ProtocolArea area) => area switch
    {
        ProtocolArea.I => I,
        ProtocolArea.Q => Q,
        ProtocolArea.M => M,
        ProtocolArea.V => V,
        ProtocolArea.SM => SM,
    };

    public bool GetBit(ProtocolArea area, int offset, int bit) => (Area(area)[offset] & (1 << bit)) != 0;

    public void SetBit(ProtocolArea area, int offset, int bit, bool value)
    {
        var bytes = Area(area);
        bytes[offset] = value ? (byte)(bytes[offset] | (1 << bit)) : (byte)(bytes[offset] & ~(1 << bit));
    }

    public ushort ReadWord(ProtocolArea area, int offset)
    {
        var b = Area(area);
        return (ushort)((b[offset] << 8) | b[offset + 1]);
    }

    public void WriteWord(ProtocolArea area, int offset, ushort value)
    {
        var b = Area(area);
        b[offset] = (byte)(value >> 8);
        b[offset + 1] = (byte)value;
    }

    public uint ReadDoubleWord(ProtocolArea area, int offset) =>
        ((uint)ReadWord(area, offset) << 16) | ReadWord(area, offset + 2);

    public void WriteDoubleWord(ProtocolArea area, int offset, uint value)
    {
        WriteWord(area, offset, (ushort)(value >> 16));
        WriteWord(area, offset + 2, (ushort)value);
    }

    private static byte[] Allocate(CpuProfile cpu, MemoryArea area) =>
        cpu.TryGetArea(area, out var range)
            ? new byte[range.ByteCount]
            : throw new ArgumentException($"{cpu.DisplayName} has no {area} area", nameof(cpu));
}
