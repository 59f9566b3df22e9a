namespace OperatorPanel.Cli.Bench;

/// <summary>
/// One workload of <c>opanel bench stl</c>: <paramref name="Requests"/> requests of <paramref name="RequestChars"/>
/// characters served one after the other by the generated handler in the interpreter, simulated time against real time.
/// </summary>
internal sealed record StlBenchResult(
    string Workload, int RequestChars, int ReplyChars, int Requests, int Answered, TimeSpan Simulated, TimeSpan Real, long Instructions)
{
    public double RequestsPerRealSecond => Answered / Real.TotalSeconds;

    public double RealMsPerRequest => Real.TotalMilliseconds / Requests;

    public double SimulatedMsPerRequest => Simulated.TotalMilliseconds / Requests;

    /// <summary>How many times faster than the real PLC and line the simulation ran (above 1: it keeps up with real time).</summary>
    public double SpeedFactor => Simulated / Real;

    public double InstructionsPerRequest => (double)Instructions / Requests;
}
