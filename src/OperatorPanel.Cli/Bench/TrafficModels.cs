using OperatorPanel.Core.Polling;

namespace OperatorPanel.Cli.Bench;

/// <summary>The polling strategies the bench compares, each as the characters one full refresh of a line costs.</summary>
internal static class TrafficModels
{
    public const string Planned = "this panel, READ LIST (steady state)";
    public const string PlainRead = "this panel, plain READ";
    public const string DefineLists = "DEFINE LISTs (once)";
    public const string PerItem = "one item per request, this protocol";
    public const string SeedPerItem = "one item per request, seed frames";
    public const string LowerBoundHex = "lower bound, hex (2 chars/byte)";
    public const string LowerBoundBinary = "lower bound, binary (1 char/byte)";

    /// <summary>
    /// The planner's frames as the polling engine sends them once its lists are defined: READ LIST (12 characters) for
    /// every frame with a list id (<see cref="ReadListAssignment"/>), plain READ for the others; the same replies.
    /// </summary>
    public static TrafficFigures FromPlan(PollPlan plan)
    {
        ArgumentNullException.ThrowIfNull(plan);
        var lists = ReadListAssignment.For(plan);
        var requests = Enumerable.Range(0, plan.FrameCount)
            .Sum(i => lists.ContainsKey(i) ? plan.CostModel.ReadListRequestChars : plan.CostModel.RequestChars(plan.Frames[i].Items.Length));
        return new(Planned, plan.FrameCount, requests, plan.ReplyChars);
    }

    /// <summary>The planner's frames as plain READs; sizes from the frame layouts (docs/protocol.md) via the cost model.</summary>
    public static TrafficFigures PlainReads(PollPlan plan)
    {
        ArgumentNullException.ThrowIfNull(plan);
        return new(PlainRead, plan.FrameCount, plan.RequestChars, plan.ReplyChars);
    }

    /// <summary>The DEFINE LIST exchanges that precede the steady state: 14 + 8N characters out, a 12-character reply back.</summary>
    public static TrafficFigures DefineListsOnce(PollPlan plan)
    {
        ArgumentNullException.ThrowIfNull(plan);
        var frames = ReadListAssignment.For(plan).Keys.Select(i => plan.Frames[i]).ToList();
        return new(
            DefineLists,
            frames.Count,
            frames.Sum(f => plan.CostModel.DefineListRequestChars(f.Items.Length)),
            frames.Count * plan.CostModel.ReplyChars(0));
    }

    /// <summary>A READ with a single item per tag, per alarm bit and per I/Q byte: the same framing, no planning.</summary>
    public static TrafficFigures OneItemPerRequest(BenchLine line, PollCostModel model)
    {
        ArgumentNullException.ThrowIfNull(line);
        ArgumentNullException.ThrowIfNull(model);
        return new(
            PerItem,
            line.Tags.Length,
            line.Tags.Length * model.RequestChars(1),
            line.Tags.Sum(t => model.ReplyChars(t.Address.LastByte - t.Address.ByteOffset + 1)));
    }

    /// <summary>The seed paper's commands of Table 1, one per item, with its binary frames.</summary>
    public static TrafficFigures SeedOneItemPerRequest(BenchLine line)
    {
        ArgumentNullException.ThrowIfNull(line);
        return new(
            SeedPerItem,
            line.Tags.Length,
            line.Tags.Sum(t => SeedFrameSizes.RequestChars(t.Address)),
            line.Tags.Sum(t => SeedFrameSizes.ReplyChars(t.Address)));
    }

    /// <summary>Only the data bytes, as this protocol must carry them (2 hex characters each): no request, no framing, no delays.</summary>
    public static TrafficFigures LowerBoundAsHex(BenchLine line) => new(LowerBoundHex, 0, 0, 2 * line.DistinctDataBytes);

    /// <summary>Only the data bytes as raw binary, one character each.</summary>
    public static TrafficFigures LowerBoundAsBinary(BenchLine line) => new(LowerBoundBinary, 0, 0, line.DistinctDataBytes);
}
