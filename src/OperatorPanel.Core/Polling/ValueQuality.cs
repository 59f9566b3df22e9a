namespace OperatorPanel.Core.Polling;

/// <summary>How far a polled value can be trusted. The rules are applied once per poll cycle.</summary>
public enum ValueQuality
{
    /// <summary>Not usable: never read yet, or the station refused the READ carrying it (an error reply).</summary>
    Bad,

    /// <summary>The last READ carrying it succeeded; the value and timestamp are from that read.</summary>
    Good,

    /// <summary>
    /// It was read once, but the most recent attempt failed on the link (no answer, corrupt reply, station offline).
    /// The value and timestamp are those of the last good read.
    /// </summary>
    Stale,
}
