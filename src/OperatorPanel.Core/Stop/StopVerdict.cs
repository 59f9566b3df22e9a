namespace OperatorPanel.Core.Stop;

/// <summary>The kind of a <see cref="StopOutcome"/>, for exhaustive switches (exit codes, JSON names) in the front ends.</summary>
public enum StopVerdict
{
    Stopped,
    StoppedReplyLost,
    NotExecuted,
    NotStopped,
    NotSent,
    NotInHandler,
    WrongCpu,
    Refused,
    Unknown,
}
