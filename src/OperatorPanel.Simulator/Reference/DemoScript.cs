namespace OperatorPanel.Simulator.Reference;

/// <summary>
/// The disturbances of the demo line, repeating every five minutes of simulated time, so that a technician watching
/// for a while sees each alarm of samples/bottling-line.opproj come and go. Times are offsets into the period, in ms;
/// the operator (<see cref="DemoOperator"/>) then acknowledges and restarts the line.
/// </summary>
internal static class DemoScript
{
    public const long Period = 300_000;

    /// <summary>The operator presses Stop (I0.2, NC) for 0.3 s: a planned stop, no alarm.</summary>
    public const long PlannedStopAt = 30_000;

    /// <summary>Compressed air dips for 2 s (I1.5 off): M2.5.</summary>
    public const long AirDipAt = 50_000;

    /// <summary>Someone opens the guard door for 6 s (I1.3 off) while the line runs: M2.3.</summary>
    public const long GuardDoorAt = 90_000;

    /// <summary>The next bottle onto the line falls over across the infeed photo eye: M2.1 once it blocks the eye.</summary>
    public const long JamAt = 130_000;

    /// <summary>The conveyor motor protection switch trips for 5 s (I1.4 off): M2.4.</summary>
    public const long MotorTripAt = 170_000;

    /// <summary>The emergency stop is pressed for 4 s (I0.0 off): M2.0, the line stops.</summary>
    public const long EStopAt = 215_000;

    public static bool StopPressed(long ms) => Within(ms, PlannedStopAt, 300);

    public static bool AirPressureLow(long ms) => Within(ms, AirDipAt, 2_000);

    public static bool GuardDoorOpen(long ms) => Within(ms, GuardDoorAt, 6_000);

    public static bool MotorTripped(long ms) => Within(ms, MotorTripAt, 5_000);

    public static bool EStopPressed(long ms) => Within(ms, EStopAt, 4_000);

    /// <summary>True on the one scan that arms the jam (scans fall on whole multiples of 10 ms).</summary>
    public static bool JamStarts(long ms) => ms % Period == JamAt;

    /// <summary>Every 37th bottle fills slowly (a sticking valve), about 1.1 s for 500 ml: longer than VW104 allows.</summary>
    public static bool FillsSlowly(int serial) => serial % 37 == 20;

    private static bool Within(long ms, long at, long duration) => ms % Period >= at && ms % Period < at + duration;
}
