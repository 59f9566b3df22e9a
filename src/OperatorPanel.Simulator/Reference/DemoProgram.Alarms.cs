using static OperatorPanel.Simulator.Reference.DemoSymbols;

namespace OperatorPanel.Simulator.Reference;

/// <summary>
/// The alarm part of the demo program: flags M2.0-M2.7 latched from their causes, cleared by Reset (I0.3) once the
/// cause has gone; fault lamp, low-product lamp, horn and FaultCode VB160 follow them.
/// </summary>
internal sealed partial class DemoProgram
{
    private const int JamAfterMs = 1_500;
    private const int HornMs = 5_000;
    private const int BatchMessageMs = 5_000;

    /// <summary>0.1 %: M2.2 comes with the low switch (20 %) and goes once the pump has the tank back to 25 %.</summary>
    private const int LowProductClearsAt = 250;

    private int _infeedBlockedMs;
    private int _hornMs;
    private int _batchMs;
    private bool _lastReset;

    private DemoAlarms LatchAlarms(PlcMemory m, double tankLevel)
    {
        // Start from the flags as they stand: the panel may have written some.
        var alarms = (DemoAlarms)m.M[AlarmByte];
        var reset = ResetButton.Get(m);
        if (reset && !_lastReset)
        {
            alarms &= ~(DemoAlarms.NeedAcknowledgement & ~CausesPresent(m));
        }

        _lastReset = reset;
        _infeedBlockedMs = InfeedBottle.Get(m) && Running ? _infeedBlockedMs + DemoProcess.ScanMs : 0;
        alarms |= Raise(!EStopHealthy.Get(m), DemoAlarms.EmergencyStop)
            | Raise(_infeedBlockedMs >= JamAfterMs, DemoAlarms.Jam)
            | Raise(!GuardDoorClosed.Get(m) && Running, DemoAlarms.GuardDoor)
            | Raise(!ConveyorMotorOk.Get(m), DemoAlarms.MotorOverload)
            | Raise(!AirPressureOk.Get(m), DemoAlarms.AirPressure);
        if (TankLevelLow.Get(m))
        {
            alarms |= DemoAlarms.LowProduct;
        }
        else if (tankLevel >= LowProductClearsAt)
        {
            alarms &= ~DemoAlarms.LowProduct;
        }

        return alarms;
    }

    private void WriteAlarms(PlcMemory m, DemoAlarms alarms)
    {
        alarms = _batchMs > 0 ? alarms | DemoAlarms.BatchComplete : alarms & ~DemoAlarms.BatchComplete;
        _batchMs = Math.Max(0, _batchMs - DemoProcess.ScanMs);
        var newFaults = alarms & ~(DemoAlarms)m.M[AlarmByte] & DemoAlarms.Faults;
        _hornMs = newFaults != 0 ? HornMs : Math.Max(0, _hornMs - DemoProcess.ScanMs);
        m.M[AlarmByte] = (byte)alarms;
        m.V[FaultCode] = Code(alarms);
        Drive(LampFault, (alarms & DemoAlarms.Faults) != 0);
        Drive(LampLowProduct, (alarms & DemoAlarms.LowProduct) != 0);
        Drive(Horn, _hornMs > 0);
    }

    /// <summary>The causes that keep a latched flag from being reset; a slow fill (M2.6) has none once it is over.</summary>
    private static DemoAlarms CausesPresent(PlcMemory m) =>
        Raise(!EStopHealthy.Get(m), DemoAlarms.EmergencyStop)
        | Raise(InfeedBottle.Get(m), DemoAlarms.Jam)
        | Raise(!GuardDoorClosed.Get(m), DemoAlarms.GuardDoor)
        | Raise(!ConveyorMotorOk.Get(m), DemoAlarms.MotorOverload)
        | Raise(!AirPressureOk.Get(m), DemoAlarms.AirPressure);

    /// <summary>FaultCode VB160: 1 + the bit number of the first active fault or warning (M2.0 = 1 ... M2.6 = 7), 0 for none.</summary>
    private static byte Code(DemoAlarms alarms)
    {
        var active = (byte)(alarms & ~DemoAlarms.BatchComplete);
        return active == 0 ? (byte)0 : (byte)(byte.TrailingZeroCount(active) + 1);
    }

    private static DemoAlarms Raise(bool cause, DemoAlarms flag) => cause ? flag : DemoAlarms.None;
}
