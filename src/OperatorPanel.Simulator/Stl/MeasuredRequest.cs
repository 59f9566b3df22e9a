namespace OperatorPanel.Simulator.Stl;

/// <summary>
/// One worst-case request served by the handler, at the StlTiming figures. <paramref name="Instructions"/> and
/// <paramref name="ExecutionTime"/>: everything the handler executed for it (its interrupt routines, including their
/// entry and exit, and its slices in OP_PANEL). <paramref name="WorstInterrupt"/>: the longest single interrupt
/// routine run, the time the CPU cannot serve another interrupt. <paramref name="WorstScan"/>: the most the handler
/// added to one scan. <paramref name="Scans"/>: scans from the request's end until the reply was started (the reply
/// delay's timed interrupt attached) or, for silence, until the port received again. <paramref name="ReplyChars"/>
/// is 0 for silence.
/// </summary>
public sealed record MeasuredRequest(
    string Name, int RequestChars, int ReplyChars, long Instructions, TimeSpan ExecutionTime, TimeSpan WorstInterrupt,
    TimeSpan WorstScan, int Scans);
