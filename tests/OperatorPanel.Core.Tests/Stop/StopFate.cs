namespace OperatorPanel.Core.Tests.Stop;

/// <summary>What happens to the STOP a <see cref="StoppablePlcLink"/> is sent.</summary>
internal enum StopFate
{
    /// <summary>STATUS 00, then the CPU is in STOP: silent.</summary>
    Executed,

    /// <summary>STATUS 00, yet the CPU keeps running and answering (a faulty handler).</summary>
    AcknowledgedButRunning,

    /// <summary>The CPU stops, but its reply is lost on the way.</summary>
    ExecutedReplyLost,

    /// <summary>The request is lost on the way: the CPU keeps running.</summary>
    RequestLost,

    /// <summary>The port failed before the frame left the PC.</summary>
    NeverSent,

    /// <summary>The handler answers with an error status.</summary>
    Refused,
}
