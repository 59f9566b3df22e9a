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
}
