using System.Collections.Immutable;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Core.Polling.Readers;

/// <summary>
/// Stored lists (docs/protocol-v2.md, "Lists" and READ CHANGES): the plan's list frames are the same every cycle, so each is
/// stored in its station once with DEFINE LIST, all of a station's lists in id order (the order the planner fitted them
/// in), and then polled with READ CHANGES, which answers only the bytes that changed. FULL is asked the first time, after
/// any READ CHANGES that brought no good reply (the PLC's copy moved on with the reply we lost), and every
/// <see cref="PollingOptions.FullReadInterval"/>. A handler without copies (<paramref name="readsChanges"/> false, from
/// its IDENTIFY), or a list answered FULL unasked, is read with READ LIST instead (until the next periodic FULL tries
/// READ CHANGES again). A station that lost its lists answers 07: its lists are defined again and the frame is read once
/// more in the same cycle. A frame whose DEFINE is refused is left to <see cref="PlainReader"/> from then on.
/// </summary>
internal sealed class ListReader(PollingContext context, StoredLists lists, bool readsChanges) : IStationReader
{
    /// <summary>V 65535: past the end of V on every CPU, so a DEFINE LIST carrying it is always refused (02).</summary>
    private static readonly ReadItem ClearingItem = new(ProtocolArea.V, ushort.MaxValue, 1);

    public async Task<IReadOnlyList<(int Frame, FrameRead Read)>> ReadAsync(IReadOnlyList<int> pending, CancellationToken cancellationToken)
    {
        ArgumentNullException.ThrowIfNull(pending);
        var index = pending[0];
        if (!lists.Stores(index))
        {
            return [];
        }

        var frame = context.Plan.Frames[index];
        var list = lists.ListOf(index);
        for (var attempt = 0; ; attempt++)
        {
            if (!lists.IsDefined(index))
            {
                if (await DefineAsync(cancellationToken).ConfigureAwait(false) is { } failed)
                {
                    return [(index, context.Judge.Failed(frame.Station, failed.Failure))];
                }

                if (!lists.IsDefined(index))
                {
                    return [];
                }
            }

            var request = Request(index, list);
            var reply = await context.Link.ExchangeAsync(request, cancellationToken).ConfigureAwait(false);
            if (reply.Failure is { } failure)
            {
                lists.CopyOf(index).Forget();
                if (request is ReadChangesRequest { Full: false } && attempt == 0)
                {
                    // The lost reply may have moved the PLC's copy on: never repeat it without FULL (protocol rule 2).
                    context.Logger.Debug("{Station}: READ CHANGES of list {List} brought no reply; asking FULL", frame.Station.Address, list);
                    continue;
                }

                return [(index, context.Judge.Failed(frame.Station, failure))];
            }

            if (reply.Response is ErrorResponse { Error: ProtocolError.ListNotDefined } && attempt == 0)
            {
                // The station lost its lists (and their copies); define them again and read once more, in this cycle.
                lists.ForgetAll();
                context.Logger.Debug("{Station}: list {List} not defined (invalidated); defining the station's lists again", frame.Station.Address, list);
                continue;
            }

            if (reply.Response is not ReadChangesResponse)
            {
                lists.CopyOf(index).Forget();
            }

            return [(index, Judge(index, frame, reply.Response))];
        }
    }

    /// <summary>Whether the list is read with READ CHANGES now (08, or with others in a 09), not READ LIST.</summary>
    public bool ReadsChanges(int index, DateTimeOffset now) => readsChanges && now >= lists.CopyOf(index).ReadListUntil;

    private FrameRead Judge(int index, PollFrame frame, PlcResponse? response) => response switch
    {
        ReadListResponse read when read.Data.Length == frame.DataBytes => context.Judge.Data(frame.Station, read.Data),
        ReadChangesResponse changes when ApplyChanges(index, changes) is { IsDefault: false } data => context.Judge.Data(frame.Station, data),
        ErrorResponse refused => context.Judge.Refused(frame, refused),
        _ => context.Judge.Unexpected(frame, response),
    };

    /// <summary>READ LIST when the station keeps no copies or the list is in its READ LIST spell, else READ CHANGES, FULL when due.</summary>
    private PlcRequest Request(int index, int list)
    {
        var copy = lists.CopyOf(index);
        var now = context.Time.GetUtcNow();
        if (!ReadsChanges(index, now))
        {
            return new ReadListRequest(lists.Station, list);
        }

        copy.AskedFull = !copy.InStep(now, context.Options.FullReadInterval);
        return new ReadChangesRequest(lists.Station, list, copy.AskedFull);
    }

    /// <summary>
    /// The list's whole data after a READ CHANGES reply: the FULL data, or the PC's copy with the pairs applied; default
    /// (and the copy forgotten, so FULL comes next) when the pairs do not fit the list (protocol rule 4).
    /// </summary>
    private ImmutableArray<byte> ApplyChanges(int index, ReadChangesResponse changes)
    {
        var copy = lists.CopyOf(index);
        if (!changes.TryApply(copy.Data.IsDefault ? [] : copy.Data.AsSpan(), out var data)
            || data.Length != context.Plan.Frames[index].DataBytes
            || (!changes.Full && copy.Data.IsDefault))
        {
            copy.Forget();
            return default;
        }

        if (changes.Full)
        {
            copy.LastFull = context.Time.GetUtcNow();
            if (!copy.AskedFull)
            {
                copy.ReadListUntil = copy.LastFull + context.Options.FullReadInterval;
                context.Logger.Debug("{Station}: list {List} answered FULL unasked (no copy for it); READ LIST until the next periodic FULL", changes.Station.Address, lists.ListOf(index));
            }
            else if (copy.RereadWithoutChanges(data))
            {
                copy.ReadListUntil = copy.LastFull + context.Options.FullReadInterval;
                context.Logger.Debug("{Station}: list {List} answered REREAD with nothing changed (no copy for it); READ LIST until the next periodic FULL", changes.Station.Address, lists.ListOf(index));
            }

            copy.BeforeReread = default;
        }

        copy.Data = data;
        return data;
    }

    /// <summary>
    /// Defines every not yet defined list of the station, in id order. Once the station has been sent a DEFINE, it may
    /// hold any of its lists (a DEFINE whose reply was lost and that the link sent again cleared the others), and a list
    /// defined below those may not fit: such a round clears the tail first and defines all of the station's lists again,
    /// in id order from an empty tail (docs/protocol-v2.md, Lists, "The PC's part"). A refused DEFINE (logged once) sends
    /// that frame back to plain READ. Returns the link failure that stopped the round, or null.
    /// </summary>
    private async Task<LinkReply.Failed?> DefineAsync(CancellationToken cancellationToken)
    {
        var frames = lists.Undefined.ToList();
        if (frames.Count > 0 && lists.SentDefine)
        {
            frames = [.. lists.Stored];
            lists.ForgetAll();
            if (await ClearAsync(frames.Select(f => f.List), cancellationToken).ConfigureAwait(false) is { } clearFailed)
            {
                return clearFailed;
            }
        }

        lists.SentDefine |= frames.Count > 0;
        foreach (var (index, list) in frames)
        {
            var frame = context.Plan.Frames[index];
            var reply = await context.Link.ExchangeAsync(new DefineListRequest(lists.Station, list, frame.Items), cancellationToken).ConfigureAwait(false);
            lists.CopyOf(index).Forget();
            switch (reply)
            {
                case LinkReply.Failed failed:
                    return failed;
                case { Response: DefineListResponse }:
                    lists.MarkDefined(index);
                    break;
                default:
                    lists.ReadPlain(index);
                    context.Logger.Warning(
                        "{Station}: DEFINE LIST {List} ({Items}) not accepted ({Reply}); reading that frame with plain READ",
                        lists.Station.Address, list, FrameJudge.Describe(frame), FrameJudge.Describe(reply.Response));
                    break;
            }
        }

        return null;
    }

    /// <summary>
    /// Empties the station's list tail: a DEFINE LIST of each id with one item past the end of V. A stored id clears
    /// every list before the item is refused (02); an id not stored is refused and changes nothing.
    /// </summary>
    private async Task<LinkReply.Failed?> ClearAsync(IEnumerable<int> ids, CancellationToken cancellationToken)
    {
        foreach (var list in ids)
        {
            if (await context.Link.ExchangeAsync(new DefineListRequest(lists.Station, list, [ClearingItem]), cancellationToken).ConfigureAwait(false) is LinkReply.Failed failed)
            {
                return failed;
            }
        }

        return null;
    }
}
