namespace OperatorPanel.Simulator.Stl;

/// <summary>
/// One worst-case request served by the handler: the instructions its interrupt routines executed (receive complete,
/// timed reply delay, transmit complete) and their estimated execution time (StlTiming, including the interrupt
/// entry overhead) = what serving this request adds to the scan. <paramref name="ReplyChars"/> is 0 for silence.
/// </summary>
public sealed record MeasuredRequest(string Name, int RequestChars, int ReplyChars, long Instructions, TimeSpan ExecutionTime);
