using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Link.V3;
using OperatorPanel.Core.Protocol.V3;
using CopyState = OperatorPanel.Core.Polling.Readers.V3StationList.CopyState;

namespace OperatorPanel.Core.Polling.Readers;

/// <summary>
/// A v3 full handler's list (docs/v3-panel-side.md): the station's frames that fit its list are defined once with 05
/// DEFINE LIST (again after the station answers 87 "no list": a restart, STOP, the mode switch) and then read together
/// in ONE 06 READ LIST per refresh: UNCHANGED keeps the values, CHANGES patches the slots it names, a whole list
/// replaces them. 06 is never repeated (the handler's copy moved on with a lost reply), so after a READ LIST without a
/// good reply the next read is 07 READ LIST FULL, after which the next 06 answers the whole list again; 07 also comes
/// every <see cref="PollingOptions.FullReadInterval"/>. A handler that refuses the DEFINE LIST itself (a compact one, or a
/// list it cannot hold) is read with READ from then on.
/// </summary>
internal sealed class V3ListReader(PollingContext context, V3Link link, V3ReaderChoice choice, Station station) : IStationReader
{
    private V3StationList _list = null!;

    public async Task<IReadOnlyList<(int Frame, FrameRead Read)>> ReadAsync(IReadOnlyList<int> pending, CancellationToken cancellationToken)
    {
        ArgumentNullException.ThrowIfNull(pending);
        if (link.IdentityOf(station) is not { } identity)
        {
            // The shape decides the list: ask it once (IDENTIFY is repeated safely); the bus re-chooses on its own IDENTIFY.
            var asked = await link.ExchangeAsync(new Protocol.IdentifyRequest(station), cancellationToken).ConfigureAwait(false);
            if (asked.Failure is { } failure)
            {
                return [(pending[0], context.Judge.Failed(station, failure))];
            }

            if (link.IdentityOf(station) is not { } answered)
            {
                return [(pending[0], context.Judge.Unexpected(context.Plan.Frames[pending[0]], asked.Response))];
            }

            identity = answered;
        }

        if (!identity.HasList)
        {
            return [];
        }

        _list = choice.ListFor(station, identity);
        var taken = _list.Frames.Where(pending.Contains).ToList();
        if (taken.Count == 0 || _list.Refused || _list.Plan is not { } plan)
        {
            return [];
        }

        for (var attempt = 0; ; attempt++)
        {
            if (!_list.Defined && await DefineAsync(plan, cancellationToken).ConfigureAwait(false) is { } defineFailed)
            {
                return All(taken, context.Judge.Failed(_list.Station, defineFailed.Failure!));
            }

            if (_list.Refused)
            {
                return [];
            }

            var full = _list.Copy == CopyState.Unknown
                || (_list.Copy == CopyState.InStep && context.Time.GetUtcNow() - _list.LastWhole >= context.Options.FullReadInterval);
            var request = full ? Request.ReadListFull(_list.Station, 0) : Request.ReadList(_list.Station, 0);
            var exchange = await link.ExchangeV3Async(request, cancellationToken).ConfigureAwait(false);
            if (exchange.Reply is not { } reply)
            {
                _list.Copy = CopyState.Unknown;
                return All(taken, context.Judge.Failed(_list.Station, exchange.Failure!));
            }

            if (reply.Status == ReplyStatus.ListNotDefined && attempt == 0)
            {
                // The station lost its list (restart, STOP, mode switch): define it again and read once more now.
                context.Logger.Debug("{Station}: no list (87); defining it again", _list.Station.Address);
                (_list.Defined, _list.Copy, _list.Known) = (false, CopyState.Unknown, default);
                continue;
            }

            return Judge(taken, plan, full, reply);
        }
    }

    private IReadOnlyList<(int Frame, FrameRead Read)> Judge(List<int> taken, ListPlan plan, bool full, Reply reply)
    {
        if (reply.Status.IsError())
        {
            _list.Copy = CopyState.Unknown;
            var refusal = $"refused READ LIST ({reply.Status})";
            return [.. taken.Select(i => (i, context.Judge.Refused(context.Plan.Frames[i], refusal)))];
        }

        var known = _list.Copy == CopyState.InStep ? _list.Known.AsSpan() : [];
        if (!ListReply.TryRead(reply, plan, out var answer) || (full && answer.Status != ReplyStatus.Ok)
            || !answer.TryApply(known, plan, out var data))
        {
            // Whatever it was, the handler's copy may have moved on: READ LIST FULL next.
            _list.Copy = CopyState.Unknown;
            var what = $"{reply.Status} with {reply.Payload.Length} bytes for a list of {plan.DataBytes}";
            return [.. taken.Select(i => (i, context.Judge.Unexpected(context.Plan.Frames[i], what)))];
        }

        _list.Known = data;
        _list.Copy = full ? CopyState.Invalid : CopyState.InStep;
        if (answer.Status == ReplyStatus.Ok)
        {
            _list.LastWhole = context.Time.GetUtcNow();
        }

        return [.. taken.Select(i => (i, context.Judge.Data(_list.Station, _list.Slice(data, i))))];
    }

    /// <summary>DEFINE LIST (retried by the link: it defines the same list again). The failure when no reply came; else null.</summary>
    private async Task<V3Exchange?> DefineAsync(ListPlan plan, CancellationToken cancellationToken)
    {
        var exchange = await link.ExchangeV3Async(plan.Request(_list.Station, 0), cancellationToken).ConfigureAwait(false);
        if (exchange.Reply is not { } reply)
        {
            return exchange;
        }

        if (reply.Status == ReplyStatus.Ok && reply.Payload.IsEmpty)
        {
            (_list.Defined, _list.Copy, _list.Known) = (true, CopyState.Invalid, default);
            return null;
        }

        _list.Refused = true;
        context.Logger.Warning("{Station}: DEFINE LIST of {Items} items not accepted ({Status}); reading its frames with READ", _list.Station.Address, plan.Items.Length, reply.Status);
        return null;
    }

    private static List<(int Frame, FrameRead Read)> All(List<int> taken, FrameRead read) => [.. taken.Select(i => (i, read))];
}
