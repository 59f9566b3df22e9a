using System.Collections.Immutable;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Cli.Bench;

/// <summary>
/// The exchanges the panel sends for a plan (protocol v2), requests encoded by Core's RequestCodec and replies sized by
/// ProtocolLimits: <see cref="Setup"/> once per connection (DEFINE LIST, then the first READ CHANGES, FULL, which fills
/// the handler's copy); <see cref="Steady"/> a refresh where every value is read in full (READ CHANGES FULL: the whole
/// list, as when every byte changed); <see cref="Idle"/> a refresh where nothing changed (READ CHANGES answering K = 0).
/// Frames without a list are plain READs in every cycle. Served in this order, each request finds the PLC in the state
/// the earlier ones left.
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

                // Nothing changed: the reply's payload is K = 0 alone.
                idle.Add(new($"READ CHANGES {list}", RequestCodec.Encode(new ReadChangesRequest(frame.Station, sequence++, list, false)), ProtocolLimits.ReplyChars(1)));
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
