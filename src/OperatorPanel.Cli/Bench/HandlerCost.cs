namespace OperatorPanel.Cli.Bench;

/// <summary>
/// What the PLC's handler takes to serve one request, from the request's '&gt;' to the moment it starts the reply
/// delay: <paramref name="Scans"/> scans (the handler works one slice per scan, so each of them also runs the user's
/// program) and <paramref name="HandlerAlone"/>, that time with the handler as the whole program (its interrupt
/// routines, its slices, the CPU's housekeeping of those scans) at the published instruction times.
/// <paramref name="Source"/> says where the figures come from: the generated handler run in the interpreter, or
/// Core's documented bound when the handler could not be run for this request.
/// </summary>
internal sealed record HandlerCost(int Scans, TimeSpan HandlerAlone, string Source)
{
    /// <summary>The handler's time on a line whose own program takes <paramref name="programScan"/> per scan.</summary>
    public TimeSpan With(TimeSpan programScan) => HandlerAlone + (programScan * Scans);
}
