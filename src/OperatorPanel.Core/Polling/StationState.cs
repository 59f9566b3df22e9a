namespace OperatorPanel.Core.Polling;

public enum StationState
{
    /// <summary>Nothing sent to it yet.</summary>
    Unknown,

    /// <summary>Its last exchange got a valid reply (an error reply included: it is on the bus and answering).</summary>
    Online,

    /// <summary>
    /// Its last exchange got no answer (timeout, no answer after retries, port unavailable) or the link threw an
    /// unexpected exception. It is still tried once per cycle.
    /// </summary>
    Offline,

    /// <summary>
    /// It acknowledged a STOP from this panel and fell silent (docs/protocol-v2.md, "07 STOP"): its port speaks PPI until
    /// someone sets RUN. Still tried once per cycle like an offline station, so RUN is noticed; its silence is logged
    /// at Debug only, and its first reply makes it <see cref="Online"/> again.
    /// </summary>
    StoppedByPanel,
}
