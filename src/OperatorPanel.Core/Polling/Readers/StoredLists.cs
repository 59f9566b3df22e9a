using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Core.Polling.Readers;

/// <summary>
/// One station's stored lists as the PC knows them (docs/protocol-v2.md, "Lists"): which frames of the plan are stored under
/// which list id (the planner's order, <see cref="ReadListAssignment"/>), which are defined in the PLC now, which went
/// back to plain READ because their DEFINE was refused, whether the station was sent a DEFINE since polling started, and
/// the PC's copy of each list (<see cref="ListCopy"/>). Read and changed by <see cref="ListReader"/> and
/// <see cref="ChangesOfListsReader"/>; kept when a new IDENTIFY chooses new readers, because the PLC keeps its lists.
/// </summary>
internal sealed class StoredLists
{
    private readonly HashSet<int> _defined = [];
    private readonly HashSet<int> _plain = [];
    private readonly Dictionary<int, ListCopy> _copies = [];

    public StoredLists(PollPlan plan, Station station)
    {
        ArgumentNullException.ThrowIfNull(plan);
        Station = station;
        Lists = [.. ReadListAssignment.For(plan).Where(l => plan.Frames[l.Key].Station == station).OrderBy(l => l.Value).Select(l => (l.Key, l.Value))];
        foreach (var (frame, _) in Lists)
        {
            _copies[frame] = new ListCopy();
        }
    }

    public Station Station { get; }

    /// <summary>The station's list frames and their ids, in id order (the order they are defined in).</summary>
    public ImmutableArray<(int Frame, int List)> Lists { get; }

    /// <summary>The station was sent a DEFINE LIST since polling started: it may hold any of its lists.</summary>
    public bool SentDefine { get; set; }

    /// <summary>The frame is read as a stored list: it has a list id and its DEFINE was not refused.</summary>
    public bool Stores(int frame) => _copies.ContainsKey(frame) && !_plain.Contains(frame);

    public int ListOf(int frame) => Lists.First(l => l.Frame == frame).List;

    public bool IsDefined(int frame) => _defined.Contains(frame);

    public ListCopy CopyOf(int frame) => _copies[frame];

    /// <summary>The lists still read as lists that are not defined in the PLC now, in id order.</summary>
    public IEnumerable<(int Frame, int List)> Undefined => Lists.Where(l => Stores(l.Frame) && !IsDefined(l.Frame));

    /// <summary>Every list still read as a list, in id order.</summary>
    public IEnumerable<(int Frame, int List)> Stored => Lists.Where(l => Stores(l.Frame));

    public void MarkDefined(int frame) => _defined.Add(frame);

    /// <summary>The PLC refused the frame's DEFINE: it is read with plain READ from now on.</summary>
    public void ReadPlain(int frame) => _plain.Add(frame);

    /// <summary>The handler cleared all of the station's lists and dropped their copies.</summary>
    public void ForgetAll()
    {
        _defined.Clear();
        foreach (var copy in _copies.Values)
        {
            copy.Forget();
        }
    }
}
