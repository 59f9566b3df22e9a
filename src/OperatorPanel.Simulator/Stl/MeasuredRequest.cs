namespace OperatorPanel.Simulator.Stl;

/// <summary>
/// One worst-case request served by the handler, at the StlTiming figures. <paramref name="Instructions"/> and
/// <paramref name="ExecutionTime"/>: everything the handler executed for it (its interrupt routines, including their
/// entry and exit, and its slices in OP_PANEL). <paramref name="WorstInterrupt"/>: the longest single interrupt
/// routine run, the time the CPU cannot serve another interrupt. <paramref name="WorstScan"/>: the most the handler
/// added to one scan. <paramref name="Scans"/>: scans from the request's end to the handler's last slice on it, the
/// one that ends the reply's check (the first chunk of the reply is on the wire by then when the check took more
/// than one pass; the rest leaves from the transmit-complete routine) or, for silence, receives again.
/// <paramref name="ReplyChars"/> is 0 for silence.
/// </summary>
public sealed record MeasuredRequest(
    string Name, int RequestChars, int ReplyChars, long Instructions, TimeSpan ExecutionTime, TimeSpan WorstInterrupt,
    TimeSpan WorstScan, int Scans);
