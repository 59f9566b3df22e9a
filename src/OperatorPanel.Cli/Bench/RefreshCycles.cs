using System.Collections.Immutable;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Cli.Bench;

/// <summary>
/// The exchanges the panel sends for a plan, encoded by Core: <see cref="Setup"/> once per connection (the lists
/// defined), <see cref="Steady"/> a refresh where every value is read in full, <see cref="Idle"/> a refresh where
/// nothing changed since the last one. Served in this order, each finds the PLC in the state the earlier ones left.
/// </summary>
internal sealed record RefreshCycles(ImmutableArray<PlannedExchange> Setup, ImmutableArray<PlannedExchange> Steady, ImmutableArray<PlannedExchange> Idle)
{
    public static RefreshCycles For(PollPlan plan)
    {
        ArgumentNullException.ThrowIfNull(plan);
        var lists = ReadListAssignment.For(plan);
        var setup = ImmutableArray.CreateBuilder<PlannedExchange>();
        var steady = ImmutableArray.CreateBuilder<PlannedExchange>();
        byte sequence = 1;
        for (var i = 0; i < plan.Frames.Length; i++)
        {
            var frame = plan.Frames[i];
            var reply = plan.CostModel.ReplyChars(frame.DataBytes);
            if (lists.TryGetValue(i, out var list))
            {
                setup.Add(new($"DEFINE LIST {list}", RequestCodec.Encode(new DefineListRequest(frame.Station, sequence++, list, frame.Items)), plan.CostModel.ReplyChars(0)));
                steady.Add(new($"READ LIST {list}", RequestCodec.Encode(new ReadListRequest(frame.Station, sequence++, list)), reply));
            }
            else
            {
                steady.Add(new($"READ {frame.Items.Length} items", RequestCodec.Encode(new ReadRequest(frame.Station, sequence++, frame.Items)), reply));
            }
        }

        // Protocol v1 has no change-only read: an idle refresh costs a full one.
        return new(setup.ToImmutable(), steady.ToImmutable(), steady.ToImmutable());
    }
}
