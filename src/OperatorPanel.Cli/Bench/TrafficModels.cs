using System.Collections.Immutable;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Cli.Bench;

/// <summary>
/// The polling strategies the bench compares, each as the characters one refresh costs; frame sizes from Core
/// (ProtocolLimits: a request with P payload bytes is 12 + 2P characters, a reply 18 + 2P).
/// </summary>
internal static class TrafficModels
{
    public const string Planned = "this panel, steady (READ CHANGES FULL)";
    public const string Idle = "this panel, idle (nothing changed)";
    public const string PlainRead = "this panel's frames as plain READs";
    public const string DefineLists = "list set-up (once)";
    public const string PerItem = "one item per request, this protocol";
    public const string SeedPerItem = "one item per request, original frames";
    public const string LowerBoundHex = "lower bound, hex (2 chars/byte)";
    public const string LowerBoundBinary = "lower bound, binary (1 char/byte)";

    /// <summary>The exchanges of one cycle as encoded (<see cref="RefreshCycles"/>).</summary>
    public static TrafficFigures FromCycle(string name, ImmutableArray<PlannedExchange> exchanges) =>
        new(name, exchanges.Length, exchanges.Sum(e => e.RequestChars), exchanges.Sum(e => e.ReplyChars));

    /// <summary>The planner's frames as plain READs, their item descriptors sent every refresh.</summary>
    public static TrafficFigures PlainReads(PollPlan plan)
    {
        ArgumentNullException.ThrowIfNull(plan);
        return new(PlainRead, plan.FrameCount, plan.Frames.Sum(f => ReadRequestChars(f.Items.Length)), plan.Frames.Sum(f => ProtocolLimits.ReplyChars(f.DataBytes)));
    }

    /// <summary>A READ with a single item per tag, per alarm bit and per I/Q byte: the same framing, no planning.</summary>
    public static TrafficFigures OneItemPerRequest(BenchLine line)
    {
        ArgumentNullException.ThrowIfNull(line);
        return new(
            PerItem,
            line.Tags.Length,
            line.Tags.Length * ReadRequestChars(1),
            line.Tags.Sum(t => ProtocolLimits.ReplyChars(t.Address.LastByte - t.Address.ByteOffset + 1)));
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

    /// <summary>READ: payload COUNT and 4 bytes (AREA OFFSET LENGTH) per item.</summary>
    private static int ReadRequestChars(int items) => ProtocolLimits.RequestChars(1 + (4 * items));
}
