using System.Globalization;
using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Simulator.Stl.Run;

/// <summary>
/// The engine of <c>opanel stl run</c>: a loaded program on a fresh simulated CPU, run scan by scan on the simulated
/// clock (no real time passes) with values set at the start or at given times, then the watched addresses read. The
/// state read is the one at the end of the last scan that completed at or before the run's time, as a real CPU shows
/// it (outputs are written at the end of the scan): never the middle of a scan.
/// </summary>
public sealed class StlRun
{
    private readonly StlProgram _program;

    public StlRun(StlProgram program)
    {
        ArgumentNullException.ThrowIfNull(program);
        _program = program;
        Plc = new StlPlc(program);
    }

    /// <summary>The CPU after <see cref="Run"/>: at the end of its last complete scan, or where it went to STOP.</summary>
    public StlPlc Plc { get; private set; }

    /// <summary>When the state read was reached: the end of the last complete scan (or the STOP); null before a run.</summary>
    public TimeSpan? ReadAt { get; private set; }

    /// <summary>True when no scan completed within the run's time (the state read is then the one at its end).</summary>
    public bool NoScanCompleted { get; private set; }

    /// <summary>
    /// Runs until <paramref name="duration"/> of simulated time, applying each setting when its time comes (settings
    /// after <paramref name="duration"/> are the caller's error: <see cref="StlSetting.TryParse"/> callers check it).
    /// The simulation is deterministic, so the end of the last complete scan is found by a first run and the CPU is
    /// then run again from power-up to exactly that moment: the state read is that scan's, whatever was read or
    /// written in the next one.
    /// </summary>
    public void Run(TimeSpan duration, IEnumerable<StlSetting> settings)
    {
        ArgumentNullException.ThrowIfNull(settings);
        var ordered = settings.Where(s => s.At <= duration).OrderBy(s => s.At).ToList();
        var end = Execution.StlTime.FromTimeSpan(duration);
        Play(Plc, ordered, end);
        if (Plc.Mode == Reference.OperatingMode.Stop || Plc.LastProgramEnd is not { } scanEnd)
        {
            NoScanCompleted = Plc.LastProgramEnd is null && Plc.Mode == Reference.OperatingMode.Run;
            ReadAt = Plc.Now;
            return;
        }

        Plc = new StlPlc(_program);
        Play(Plc, ordered, scanEnd);
        ReadAt = Execution.StlTime.ToTimeSpan(scanEnd);
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

    /// <summary>Runs <paramref name="plc"/> to <paramref name="end"/> (ns), applying the settings due by then in order.</summary>
    private static void Play(StlPlc plc, List<StlSetting> settings, long end)
    {
        foreach (var setting in settings.Where(s => Execution.StlTime.FromTimeSpan(s.At) <= end))
        {
            plc.RunTo(Execution.StlTime.FromTimeSpan(setting.At));
            Apply(plc, setting);
        }

        plc.RunTo(end);
    }

    private static void Apply(StlPlc plc, StlSetting setting)
    {
        var address = setting.Address;
        var bytes = address.Area == MemoryArea.I ? plc.InputImage : plc.AreaBytes(address.Area);
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
