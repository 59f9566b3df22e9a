namespace OperatorPanel.Core.Polling;

/// <summary>The outcome of one poll cycle: failures are counted here and in the station statuses, never thrown.</summary>
/// <param name="Cycle">Number of the cycle since the engine was created, from 1.</param>
/// <param name="StartedAt">Clock time the cycle started; the minimum period counts from here.</param>
/// <param name="FinishedAt">Clock time the last READ of the cycle ended.</param>
/// <param name="FramesSent">Frames of the plan whose READ was attempted (a stored list counts once, whether one 09 READ CHANGES OF LISTS brought it with others or its own exchange); frames of a station found offline earlier in the cycle are skipped.</param>
/// <param name="FramesFailed">Attempted READs that got no usable reply or an error reply.</param>
/// <param name="JobsDone">Jobs of the bus's queue (writes, IDENTIFY, STOP) run between the READs of this cycle.</param>
/// <param name="ValuesChanged">Values whose value or quality changed, all published in one batch.</param>
public sealed record PollResult(
    long Cycle,
    DateTimeOffset StartedAt,
    DateTimeOffset FinishedAt,
    int FramesSent,
    int FramesFailed,
    int JobsDone,
    int ValuesChanged);
