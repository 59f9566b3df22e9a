using System.Collections.Immutable;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Protocol.V3;

namespace OperatorPanel.Cli.Bench.V3;

/// <summary>One v3 exchange of the bench: its name, the request's bytes, and the reply's bytes as Codec encodes it.</summary>
internal sealed record V3PlannedExchange(string Name, byte[] Request, int ReplyBytes);

/// <summary>
/// The v3 frames the panel sends for a line (docs/protocol.md section 2): the station's plan frames fitted into one
/// list as the panel's V3StationList fits them (in plan order, each taken while the list still fits the full handler's
/// 32 slots and 128 bytes, ListPlan), defined once with DEFINE LIST, then one READ LIST per refresh. Steady = 07 READ
/// LIST FULL (every value read in full: the reply carries the whole list); idle = 06 READ LIST answered 81 UNCHANGED
/// (the 06 before it, with the copy not yet valid, is answered whole and fills the copy). Sizes from Codec.
/// </summary>
internal sealed record V3RefreshFrames(
    ListPlan List, int FramesLeftOut, ImmutableArray<V3PlannedExchange> Setup, V3PlannedExchange Steady, V3PlannedExchange FillCopy, V3PlannedExchange Idle)
{
    public static bool TryCreate(BenchLine line, out V3RefreshFrames frames, out string error)
    {
        ArgumentNullException.ThrowIfNull(line);
        var ranges = new List<ReadItem>();
        ListPlan? list = null;
        var leftOut = 0;
        foreach (var frame in line.Plan().Frames.Where(f => f.Station == line.Station && !f.Items.IsEmpty))
        {
            if (ListPlan.TryMake([.. ranges, .. frame.Items], HandlerShape.Full, ListPlan.AreaBytesOf(line.Cpu), out var fitted))
            {
                ranges.AddRange(frame.Items);
                list = fitted;
            }
            else
            {
                leftOut++;
            }
        }

        frames = null!;
        if (list is null)
        {
            error = "no frame of the line fits a v3 list";
            return false;
        }

        byte sequence = 0;
        byte Next() => sequence = (byte)((sequence + 1) % Limits.SequenceCount);
        var s = line.Station;
        var whole = ReplyBytes(list.DataBytes);
        frames = new V3RefreshFrames(
            list,
            leftOut,
            [
                new("DEFINE LIST", Codec.Encode(list.Request(s, Next())), ReplyBytes(0)),
                new("READ LIST FULL (first read)", Codec.Encode(Request.ReadListFull(s, Next())), whole),
            ],
            new("READ LIST FULL (steady: the whole list)", Codec.Encode(Request.ReadListFull(s, Next())), whole),
            new("READ LIST (copy not valid: the whole list)", Codec.Encode(Request.ReadList(s, Next())), whole),
            new("READ LIST (idle: UNCHANGED)", Codec.Encode(Request.ReadList(s, Next())), ReplyBytes(0)));
        error = string.Empty;
        return true;
    }

    /// <summary>A reply's bytes on the wire with <paramref name="payload"/> bytes of payload, as Codec encodes it.</summary>
    public static int ReplyBytes(int payload) => Codec.Encode(new Reply(ReplyStatus.Ok, 0, [.. new byte[payload]])).Length;
}
