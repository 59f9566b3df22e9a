namespace OperatorPanel.Simulator.Reference;

/// <summary>
/// The operator at the demo line, pressing buttons as a person would: Reset (I0.3) a few seconds after the cause of a
/// latched alarm has gone, Start (I0.1) once the line has stood still for a while with nothing wrong.
/// </summary>
internal sealed class DemoOperator
{
    private const int PressMs = 300;
    private const int ResetAfterMs = 4_000;
    private const int StartAfterMs = 3_000;

    private int _calmMs;
    private int _idleMs;
    private int _resetLeftMs;
    private int _startLeftMs;

    public bool ResetPressed => _resetLeftMs > 0;

    public bool StartPressed => _startLeftMs > 0;

    /// <summary>One scan: <paramref name="fieldHealthy"/> means every cause of a fault alarm has gone.</summary>
    public void Step(bool fieldHealthy, DemoAlarms alarms, bool lineRunning, bool stopButtonPressed)
    {
        _resetLeftMs = Math.Max(0, _resetLeftMs - DemoProcess.ScanMs);
        _startLeftMs = Math.Max(0, _startLeftMs - DemoProcess.ScanMs);
        var latched = (alarms & DemoAlarms.NeedAcknowledgement) != 0;

        _calmMs = latched && fieldHealthy ? _calmMs + DemoProcess.ScanMs : 0;
        if (_calmMs >= ResetAfterMs)
        {
            _resetLeftMs = PressMs;
            _calmMs = 0;
        }

        _idleMs = !lineRunning && !latched && fieldHealthy && !stopButtonPressed ? _idleMs + DemoProcess.ScanMs : 0;
        if (_idleMs >= StartAfterMs)
        {
            _startLeftMs = PressMs;
            _idleMs = 0;
        }
    }
}
