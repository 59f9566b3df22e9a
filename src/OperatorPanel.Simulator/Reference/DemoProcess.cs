namespace OperatorPanel.Simulator.Reference;

/// <summary>
/// The bottle filler of samples/bottling-line.opproj run on an <see cref="IDemoPlc"/> (either model) by simulated time only (no
/// clocks, no randomness), one scan every 10 ms. Each scan the machine side (<see cref="DemoField"/>: conveyor,
/// photo eyes, fill head, tank, scripted disturbances) and the operator (<see cref="DemoOperator"/>) set the inputs,
/// then, in RUN, the program (<see cref="DemoProgram"/>) sets the outputs, tags and alarms. Every value follows from
/// the elapsed time alone, as long as the panel writes nothing.
/// </summary>
public sealed class DemoProcess
{
    internal const int ScanMs = 10;

    public static readonly TimeSpan ScanPeriod = TimeSpan.FromMilliseconds(ScanMs);

    private readonly IDemoPlc _plc;
    private readonly DemoField _field = new();
    private readonly DemoOperator _operator = new();
    private readonly DemoProgram _program;
    private TimeSpan _pending;
    private long _scans;

    public DemoProcess(IDemoPlc plc)
    {
        ArgumentNullException.ThrowIfNull(plc);
        _plc = plc;
        _program = new DemoProgram(plc);
    }

    /// <summary>Simulated time run so far, in whole scans.</summary>
    public TimeSpan Elapsed => ScanPeriod * _scans;

    public void Advance(TimeSpan elapsed)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(elapsed, TimeSpan.Zero);
        _pending += elapsed;
        while (_pending >= ScanPeriod)
        {
            _pending -= ScanPeriod;
            _scans++;
            Scan(_scans * ScanMs);
        }
    }

    private void Scan(long ms)
    {
        var m = _plc.Memory;
        _field.Step(m, ms);
        _operator.Step(_field.IsHealthy(ms), (DemoAlarms)m.M[DemoSymbols.AlarmByte], _program.Running, DemoScript.StopPressed(ms));
        _field.WriteInputs(m, ms, _operator);
        if (_plc.Mode == OperatingMode.Run)
        {
            _program.Scan(m, ms, _field.TankLevel);
        }

        // Scan times 3-6 ms in a fixed pattern, so SMW22/24/26 show something plausible and repeatable.
        _plc.CompleteScan((ushort)(3 + (_scans % 4)));
    }
}
