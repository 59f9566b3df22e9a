using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Protocol.V3;

namespace OperatorPanel.Core.Polling.Readers;

/// <summary>
/// One station's v3 list as the PC knows it: which of the station's plan frames it holds (in plan order, as many as fit
/// the handler's LIST_ITEMS and LIST_BYTES: <see cref="ListPlan"/>), where each frame's bytes lie in the list data,
/// whether the station holds the list now, and what the PC knows of the handler's copy (<see cref="CopyState"/>).
/// </summary>
internal sealed class V3StationList
{
    /// <summary>Per frame, where each of its ranges starts in the list data (a widened range's bytes end its item, so ranges need not follow one another).</summary>
    private readonly Dictionary<int, ImmutableArray<(int Place, int Length)>> _places = [];

    public V3StationList(PollPlan plan, Station station, HandlerShape shape, Func<ProtocolArea, int>? areaBytes = null)
    {
        ArgumentNullException.ThrowIfNull(plan);
        (Station, Shape) = (station, shape);
        var ranges = new List<ReadItem>();
        var frames = new List<int>();
        ListPlan? fitted = null;
        for (var index = 0; index < plan.Frames.Length; index++)
        {
            var frame = plan.Frames[index];
            if (frame.Station != station || frame.Items.IsEmpty)
            {
                continue;
            }

            if (!ListPlan.TryMake([.. ranges, .. frame.Items], shape, areaBytes, out var plan2))
            {
                continue;
            }

            _places[index] = [.. frame.Items.Select((item, k) => (plan2.Places[ranges.Count + k], item.Length))];
            ranges.AddRange(frame.Items);
            frames.Add(index);
            fitted = plan2;
        }

        (Frames, Plan) = ([.. frames], fitted);
    }

    public Station Station { get; }

    public HandlerShape Shape { get; }

    /// <summary>The frames the list reads, in plan order; empty when none fits.</summary>
    public ImmutableArray<int> Frames { get; }

    /// <summary>The list as DEFINE LIST sends it; null when no frame fits.</summary>
    public ListPlan? Plan { get; }

    /// <summary>The station holds the list (a DEFINE LIST was answered OK and no reply said "no list" since).</summary>
    public bool Defined { get; set; }

    /// <summary>The handler refused the DEFINE LIST itself (a compact handler, or a list it cannot hold): READ from now on.</summary>
    public bool Refused { get; set; }

    public CopyState Copy { get; set; } = CopyState.Unknown;

    /// <summary>The list data of the last good reply; default before one.</summary>
    public ImmutableArray<byte> Known { get; set; }

    /// <summary>When the last whole list came (READ LIST FULL or a whole READ LIST answer).</summary>
    public DateTimeOffset LastWhole { get; set; }

    /// <summary>Frame <paramref name="index"/>'s bytes in <paramref name="data"/>: each of its ranges' bytes from that range's place, in order.</summary>
    public ImmutableArray<byte> Slice(ImmutableArray<byte> data, int index) => [.. _places[index].SelectMany(r => data.Slice(r.Place, r.Length))];

    /// <summary>What the PC knows of the handler's copy, which READ LIST compares with and renews.</summary>
    public enum CopyState
    {
        /// <summary>A READ LIST reply was lost: the copy may hold what the PC never saw; READ LIST FULL next.</summary>
        Unknown,

        /// <summary>After DEFINE LIST or READ LIST FULL: the next READ LIST answers the whole list.</summary>
        Invalid,

        /// <summary>The copy holds <see cref="Known"/>: READ LIST answers UNCHANGED, CHANGES or the whole list against it.</summary>
        InStep,
    }
}
