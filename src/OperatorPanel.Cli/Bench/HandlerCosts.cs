using System.Collections.Immutable;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Cli.Bench;

/// <summary>
/// The handler's cost for every exchange of <see cref="RefreshCycles"/>: measured by serving them in order to the
/// generated handler (<see cref="HandlerProbe"/>), or, for an exchange the handler did not answer, Core's bound
/// (<see cref="HandlerTurnaround"/> scans, each with the handler's largest slice and the user's program, then the reply
/// delay and the reply without pauses), labelled as such.
/// </summary>
internal sealed record HandlerCosts(ImmutableArray<HandlerCost> Steady, ImmutableArray<HandlerCost> Idle, ImmutableArray<string> Problems)
{
    /// <summary>The most one handler slice adds to a scan (docs/protocol-v2.md section 7: "up to 10 ms of the handler").</summary>
    public const double SliceBoundMs = 10;

    public static HandlerCosts Measure(RefreshCycles cycles, LinkTimeModel model, HandlerProbe? probe, string? probeError)
    {
        ArgumentNullException.ThrowIfNull(cycles);
        ArgumentNullException.ThrowIfNull(model);
        var problems = ImmutableArray.CreateBuilder<string>();
        if (probe is null)
        {
            problems.Add($"handler not run: {probeError}");
        }

        HandlerCost Serve(PlannedExchange exchange)
        {
            if (probe is null)
            {
                return Bound(exchange, model);
            }

            if (probe.TryServe(exchange.Request, out var cost, out var replyChars, out var error))
            {
                if (replyChars != exchange.ReplyChars)
                {
                    problems.Add($"{exchange.Name}: the handler answered {replyChars} characters, Core sizes the reply at {exchange.ReplyChars}");
                }

                // The link's reply timeout allows Core's bound of scans; a handler that takes more risks timeouts.
                var bound = LinkBound(exchange);
                if (cost!.Scans > bound)
                {
                    problems.Add($"{exchange.Name}: the handler took {cost.Scans} scans, more than Core's HandlerTurnaround bound of {bound}");
                }

                return cost;
            }

            problems.Add($"{exchange.Name}: {error}; Core's bound used");
            return Bound(exchange, model);
        }

        foreach (var exchange in cycles.Setup)
        {
            Serve(exchange);
        }

        var steady = cycles.Steady.Select(Serve).ToImmutableArray();
        var idle = cycles.Idle.Select(Serve).ToImmutableArray();
        return new(steady, idle, problems.ToImmutable());
    }

    /// <summary>
    /// The scans the link's reply timeout allows for the exchange (<see cref="HandlerTurnaround.ScansFor(PlcRequest, int)"/>:
    /// the longest reply the request can get, and the copy comparisons of READ CHANGES and READ CHANGES OF LISTS); for
    /// bytes that are no request, the bound of their characters alone.
    /// </summary>
    public static int LinkBound(PlannedExchange exchange)
    {
        ArgumentNullException.ThrowIfNull(exchange);
        return FrameCodec.TryDecode(exchange.Request, out var frame, out _) && RequestCodec.TryParse(frame, null, out var request, out _)
            ? HandlerTurnaround.ScansFor(request, exchange.RequestChars)
            : HandlerTurnaround.ScansFor(exchange.RequestChars, exchange.ReplyChars);
    }

    public static HandlerCost Bound(PlannedExchange exchange, LinkTimeModel model)
    {
        ArgumentNullException.ThrowIfNull(exchange);
        ArgumentNullException.ThrowIfNull(model);
        var scans = HandlerTurnaround.ScansFor(exchange.RequestChars, exchange.ReplyChars);
        return new HandlerCost(
            scans,
            TimeSpan.FromMilliseconds((scans * (SliceBoundMs + model.ProgramScanMs)) + model.ReplyDelayMs),
            TimeSpan.FromMilliseconds(exchange.ReplyChars * model.Line.CharacterMs),
            "bound: Core HandlerTurnaround scans x (10 ms slice + user program), then the reply delay (handler not run)");
    }
}
