using OperatorPanel.Core.Link;
using Serilog;

namespace OperatorPanel.Core.Polling.Readers;

/// <summary>What the readers and the writer of one bus share: its plan, its link, its station states and its clock.</summary>
internal sealed record PollingContext(PollPlan Plan, IPlcLink Link, FrameJudge Judge, PollingOptions Options, TimeProvider Time, ILogger Logger)
{
    /// <summary>The PPI link of a bus that speaks PPI (its stations are read and written over it); null on a Freeport bus.</summary>
    public PpiLink? Ppi { get; init; }

    /// <summary>The v3 link of a bus that speaks protocol v3 (also <see cref="Link"/>); null on a v2 or PPI bus.</summary>
    public Link.V3.V3Link? V3 { get; init; }
}
