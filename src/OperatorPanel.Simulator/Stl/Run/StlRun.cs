using System.Globalization;
using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Simulator.Stl.Run;

/// <summary>
/// The engine of <c>opanel stl run</c>: a loaded program on a fresh simulated CPU, run scan by scan on the simulated
/// clock (no real time passes) with values set at the start or at given times, then the watched addresses read.
/// </summary>
public sealed class StlRun
{
    public StlRun(StlProgram program)
    {
        ArgumentNullException.ThrowIfNull(program);
        Plc = new StlPlc(program);
    }

    public StlPlc Plc { get; }

    /// <summary>Runs until <paramref name="duration"/> of simulated time, applying each setting when its time comes.</summary>
    public void Run(TimeSpan duration, IEnumerable<StlSetting> settings)
    {
        ArgumentNullException.ThrowIfNull(settings);
        foreach (var setting in settings.Where(s => s.At <= duration).OrderBy(s => s.At))
        {
            Plc.RunUntil(setting.At);
            Apply(setting);
        }

        Plc.RunUntil(duration);
    }

    /// <summary>The watched value: bits 0/1, bytes unsigned, words INT, double words DINT (or the real), T/C current values.</summary>
    public double Read(StlWatch watch)
    {
        ArgumentNullException.ThrowIfNull(watch);
        var operand = watch.Operand;
        return operand.Area switch
        {
            MemoryArea.T => watch.IsBitOfTimerOrCounter ? Bit(Plc.TimerBitValue(operand.ByteOffset)) : Plc.TimerCurrentValue(operand.ByteOffset),
            MemoryArea.C => watch.IsBitOfTimerOrCounter ? Bit(Plc.CounterBitValue(operand.ByteOffset)) : Plc.CounterCurrentValue(operand.ByteOffset),
            MemoryArea.AC => (int)Plc.Accumulator(operand.ByteOffset),
            MemoryArea.I or MemoryArea.Q or MemoryArea.M or MemoryArea.V or MemoryArea.SM or MemoryArea.S or MemoryArea.AI or MemoryArea.AQ or MemoryArea.HC or MemoryArea.L => ReadArea(watch),
        };
    }

    /// <summary>The value as printed: integers in decimal, reals with up to 7 significant digits.</summary>
    public string Format(StlWatch watch) => Read(watch).ToString(watch.IsReal ? "G7" : "0", CultureInfo.InvariantCulture);

    private static int Bit(bool value) => value ? 1 : 0;

    private double ReadArea(StlWatch watch)
    {
        var operand = watch.Operand;
        var bytes = Plc.AreaBytes(operand.Area);
        var offset = operand.ByteOffset;
        return operand.Width switch
        {
            AccessWidth.Bit => (bytes[offset] >> operand.Bit!.Value) & 1,
            AccessWidth.Byte => bytes[offset],
            AccessWidth.Word => (short)((bytes[offset] << 8) | bytes[offset + 1]),
            AccessWidth.DoubleWord => watch.IsReal ? (double)BitConverter.UInt32BitsToSingle(DoubleWord(bytes, offset)) : (int)DoubleWord(bytes, offset),
        };
    }

    private static uint DoubleWord(byte[] bytes, int offset) =>
        (uint)((bytes[offset] << 24) | (bytes[offset + 1] << 16) | (bytes[offset + 2] << 8) | bytes[offset + 3]);

    private void Apply(StlSetting setting)
    {
        var address = setting.Address;
        var bytes = address.Area == MemoryArea.I ? Plc.InputImage : Plc.AreaBytes(address.Area);
        var offset = address.ByteOffset;
        if (address.Bit is { } bit)
        {
            bytes[offset] = setting.Value != 0 ? (byte)(bytes[offset] | (1 << bit)) : (byte)(bytes[offset] & ~(1 << bit));
            return;
        }

        var count = address.Width.ByteCount();
        for (var i = count - 1; i >= 0; i--)
        {
            bytes[offset + i] = (byte)(setting.Value >> (8 * (count - 1 - i)));
        }
    }
}
