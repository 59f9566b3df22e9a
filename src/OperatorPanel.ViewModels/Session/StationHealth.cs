namespace OperatorPanel.ViewModels.Session;

/// <summary>What the status bar shows per station.</summary>
public enum StationHealth
{
    /// <summary>Not connected, or nothing exchanged yet.</summary>
    Unknown,

    Online,

    /// <summary>The port is missing or the station never answered.</summary>
    Offline,

    /// <summary>
    /// It answered earlier and now does not: in STOP or with the mode switch at TERM the CPU hands the port back to PPI and
    /// ignores Freeport frames (docs/protocol.md, "TERM and STOP"), which the panel cannot tell from a pulled cable.
    /// </summary>
    Stopped,

    /// <summary>IDENTIFY reported a protocol version this panel does not speak: the PLC runs another handler.</summary>
    HandlerMismatch,

    /// <summary>
    /// This panel put it into STOP and it fell silent (Core/Stop/RemoteStop): its port speaks PPI until someone sets
    /// RUN. Not "offline": the panel knows why it is silent.
    /// </summary>
    StoppedByPanel,

    /// <summary>
    /// It ignores the panel's frames but answered a v2 or v1 IDENTIFY: it runs an Operator Panel handler of an older
    /// protocol, which must be generated again and downloaded (Core/Link/V3/HandlerBeforeV3, PlcErrorKind.HandlerOutdated).
    /// </summary>
    HandlerOutdated,
}
