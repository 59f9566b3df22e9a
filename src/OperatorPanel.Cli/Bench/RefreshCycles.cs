using System.Collections.Immutable;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Cli.Bench;

/// <summary>
/// The exchanges the panel sends for a plan (protocol v2), requests encoded by Core's RequestCodec and replies sized by
/// ProtocolLimits: <see cref="Setup"/> once per connection (DEFINE LIST, then the first READ CHANGES, FULL, which fills
/// the handler's copy); <see cref="Steady"/> a refresh where every value is read in full (READ CHANGES FULL: the whole
/// list, as when every byte changed); <see cref="Idle"/> a refresh where nothing changed: one 09 READ CHANGES OF LISTS
/// per station over all its lists, answering K = 0 for each (the handler StlGen generates has FEATURES bit 2, so the
/// panel reads its lists in step so: docs/protocol-v2.md, 09, PC rules). Frames without a list are plain READs in every
/// cycle. Served in this order, each request finds the PLC in the state the earlier ones left.
/// </summary>
internal sealed record RefreshCycles(ImmutableArray<PlannedExchange> Setup, ImmutableArray<PlannedExchange> Steady, ImmutableArray<PlannedExchange> Idle)
{
    public static RefreshCycles For(PollPlan plan)
    {
        ArgumentNullException.ThrowIfNull(plan);
        var lists = ReadListAssignment.For(plan);
        var setup = ImmutableArray.CreateBuilder<PlannedExchange>();
        var steady = ImmutableArray.CreateBuilder<PlannedExchange>();
        var idle = ImmutableArray.CreateBuilder<PlannedExchange>();
        byte sequence = 1;
        for (var i = 0; i < plan.Frames.Length; i++)
        {
            var frame = plan.Frames[i];
            if (lists.TryGetValue(i, out var list))
            {
                var full = ProtocolLimits.ListReplyChars(frame.DataBytes);
                setup.Add(new($"DEFINE LIST {list}", RequestCodec.Encode(new DefineListRequest(frame.Station, sequence++, list, frame.Items)), ProtocolLimits.ReplyChars(0)));
                setup.Add(new($"READ CHANGES {list} FULL", RequestCodec.Encode(new ReadChangesRequest(frame.Station, sequence++, list, true)), full));
                steady.Add(new($"READ CHANGES {list} FULL", RequestCodec.Encode(new ReadChangesRequest(frame.Station, sequence++, list, true)), full));
                var stationLists = lists.Where(l => plan.Frames[l.Key].Station == frame.Station).Select(l => l.Value).Order().ToList();
                if (list == stationLists[0])
                {
                    // Nothing changed: the reply's payload is one K = 0 per list.
                    var request = new ReadChangesOfListsRequest(frame.Station, sequence++, ReadChangesOfListsRequest.MaskOf(stationLists));
                    idle.Add(new($"READ CHANGES OF LISTS {string.Join("+", stationLists)}", RequestCodec.Encode(request), ProtocolLimits.ReplyChars(stationLists.Count)));
                }
            }
            else
            {
                var read = new PlannedExchange(
                    $"READ {frame.Items.Length} items", RequestCodec.Encode(new ReadRequest(frame.Station, sequence++, frame.Items)), ProtocolLimits.ReplyChars(frame.DataBytes));
                steady.Add(read);
                idle.Add(read with { Request = RequestCodec.Encode(new ReadRequest(frame.Station, sequence++, frame.Items)) });
            }
        }

        return new(setup.ToImmutable(), steady.ToImmutable(), idle.ToImmutable());
    }
}
