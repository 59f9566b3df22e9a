using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Core.Polling;

/// <summary>
/// Stored lists (docs/protocol.md, "Lists" and READ CHANGES): the plan's list frames are the same every cycle, so each is
/// stored in its station once with DEFINE LIST, all of a station's lists in id order (the order the planner fitted them
/// in), and then polled with READ CHANGES, which answers only the bytes that changed. FULL is asked the first time, after
/// any READ CHANGES that brought no good reply (the PLC's copy moved on with the reply we lost), and every
/// <see cref="PollingOptions.FullReadInterval"/>. A station whose handler keeps no copies, or a list answered FULL unasked,
/// is read with READ LIST instead (until the next periodic FULL tries READ CHANGES again). A station that lost its lists
/// answers 07: its lists are defined again and the frame is read once more in the same cycle. A frame whose DEFINE is
/// refused is read with plain READs from then on. A handler with 09 gets the lists in step in one exchange first
/// (PollingEngine.ChangesOfLists.cs); what that does not bring comes here.
/// </summary>
public sealed partial class PollingEngine
{
    private readonly ImmutableDictionary<int, int> _listIds;
    /// <summary>V 65535: past the end of V on every CPU, so a DEFINE LIST carrying it is always refused (02).</summary>
    private static readonly ReadItem ClearingItem = new(ProtocolArea.V, ushort.MaxValue, 1);

    private readonly HashSet<int> _definedFrames = [];

    /// <summary>Stations sent a DEFINE LIST since the engine started: they may hold any of their lists.</summary>
    private readonly HashSet<Station> _stationsSentDefine = [];
    private readonly HashSet<int> _plainFrames = [];
    private readonly Dictionary<int, ListCopy> _copies = [];
    private readonly HashSet<Station> _stationsWithoutCopies = [];

    /// <summary>
    /// Poll the plan's lists as stored lists (default) or with plain READs only, one exchange per frame and cycle. Set
    /// before <see cref="RunAsync"/>.
    /// </summary>
    public bool UseReadLists { get; init; } = true;

    /// <summary>READ CHANGES or READ LIST, and how often FULL. Set before <see cref="RunAsync"/>.</summary>
    public PollingOptions Options { get; init; } = new();

    /// <summary>
    /// What an IDENTIFY reply says about the station's handler: without READ CHANGES copies (FEATURES bit 1 clear or
    /// COPY_BYTES 0) every READ CHANGES would answer FULL, 4 characters longer than READ LIST, so its lists are read with
    /// READ LIST; with FEATURES bit 2 its lists in step are read with one 09 READ CHANGES OF LISTS a cycle. Call from the
    /// thread that talks to the engine; takes effect from the next exchange.
    /// </summary>
    public void NoteIdentity(IdentifyResponse identity)
    {
        ArgumentNullException.ThrowIfNull(identity);
        lock (_gate)
        {
            if (identity.HasChangesOfLists)
            {
                _stationsWithChangesOfLists.Add(identity.Station);
            }
            else
            {
                _stationsWithChangesOfLists.Remove(identity.Station);
            }

            if (identity.HasCopies && identity.CopyBytes > 0)
            {
                _stationsWithoutCopies.Remove(identity.Station);
            }
            else
            {
                _stationsWithoutCopies.Add(identity.Station);
            }
        }
    }

    /// <summary>READ CHANGES or READ LIST when the frame has a list (defining the station's lists first when needed), else a plain READ.</summary>
    private async Task<LinkReply> ExchangeFrameAsync(int index, CancellationToken cancellationToken)
    {
        var frame = _plan.Frames[index];
        if (!UseReadLists || !_listIds.TryGetValue(index, out var list) || _plainFrames.Contains(index))
        {
            return await ReadPlainAsync(frame, cancellationToken).ConfigureAwait(false);
        }

        for (var attempt = 0; ; attempt++)
        {
            if (!_definedFrames.Contains(index))
            {
                if (await DefineListsAsync(frame.Station, cancellationToken).ConfigureAwait(false) is { } defineFailed)
                {
                    return defineFailed;
                }

                if (!_definedFrames.Contains(index))
                {
                    return await ReadPlainAsync(frame, cancellationToken).ConfigureAwait(false);
                }
            }

            var request = ListRequest(index, list);
            var reply = await _link.ExchangeAsync(request, cancellationToken).ConfigureAwait(false);
            if (reply is LinkReply.Failed)
            {
                CopyOf(index).Forget();
                if (request is ReadChangesRequest { Full: false } && attempt == 0)
                {
                    // The lost reply may have moved the PLC's copy on: never repeat it without FULL (protocol rule 2).
                    _logger.Debug("{Station}: READ CHANGES of list {List} brought no reply; asking FULL", frame.Station.Address, list);
                    continue;
                }

                return reply;
            }

            if (reply.Response is ErrorResponse { Error: ProtocolError.ListNotDefined } && attempt == 0)
            {
                // The station lost its lists (and their copies); define them again and read once more, in this cycle.
                ForgetLists(frame.Station);
                _logger.Debug("{Station}: list {List} not defined (invalidated); defining the station's lists again", frame.Station.Address, list);
                continue;
            }

            if (reply.Response is not ReadChangesResponse)
            {
                CopyOf(index).Forget();
            }

            return reply;
        }
    }

    /// <summary>READ LIST when the station keeps no copies or the list is in its READ LIST spell, else READ CHANGES, FULL when due.</summary>
    private PlcRequest ListRequest(int index, int list)
    {
        var frame = _plan.Frames[index];
        var copy = CopyOf(index);
        var now = _time.GetUtcNow();
        if (!ReadsChanges(index, now))
        {
            return new ReadListRequest(frame.Station, list);
        }

        copy.AskedFull = !copy.InStep(now, Options.FullReadInterval);
        return new ReadChangesRequest(frame.Station, list, copy.AskedFull);
    }

    /// <summary>Whether the list at <paramref name="index"/> is read with READ CHANGES (08 or 09) now, not READ LIST.</summary>
    private bool ReadsChanges(int index, DateTimeOffset now)
    {
        bool withoutCopies;
        lock (_gate) { withoutCopies = _stationsWithoutCopies.Contains(_plan.Frames[index].Station); }
        return Options.UseReadChanges && !withoutCopies && now >= CopyOf(index).ReadListUntil;
    }

    /// <summary>
    /// The list's whole data after a READ CHANGES reply: the FULL data, or the PC's copy with the pairs applied; default
    /// (and the copy forgotten, so FULL comes next) when the pairs do not fit the list (protocol rule 4).
    /// </summary>
    private ImmutableArray<byte> ApplyChanges(int index, ReadChangesResponse changes)
    {
        var copy = CopyOf(index);
        if (!changes.TryApply(copy.Data.IsDefault ? [] : copy.Data.AsSpan(), out var data)
            || data.Length != _plan.Frames[index].DataBytes
            || (!changes.Full && copy.Data.IsDefault))
        {
            copy.Forget();
            return default;
        }

        if (changes.Full)
        {
            copy.LastFull = _time.GetUtcNow();
            if (!copy.AskedFull)
            {
                copy.ReadListUntil = copy.LastFull + Options.FullReadInterval;
                _logger.Debug("{Station}: list {List} answered FULL unasked (no copy for it); READ LIST until the next periodic FULL", changes.Station.Address, _listIds[index]);
            }
            else if (copy.RereadWithoutChanges(data))
            {
                copy.ReadListUntil = copy.LastFull + Options.FullReadInterval;
                _logger.Debug("{Station}: list {List} answered REREAD with nothing changed (no copy for it); READ LIST until the next periodic FULL", changes.Station.Address, _listIds[index]);
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
    /// in id order from an empty tail (docs/protocol.md, Lists, "The PC's part"). A refused DEFINE (logged once) sends
    /// that frame back to plain READ. Returns the link failure that stopped the round, or null.
    /// </summary>
    private async Task<LinkReply.Failed?> DefineListsAsync(Station station, CancellationToken cancellationToken)
    {
        var frames = _listIds.Where(l => _plan.Frames[l.Key].Station == station && !_definedFrames.Contains(l.Key) && !_plainFrames.Contains(l.Key))
            .OrderBy(l => l.Value).ToList();
        if (frames.Count > 0 && !_stationsSentDefine.Add(station))
        {
            frames = [.. _listIds.Where(l => _plan.Frames[l.Key].Station == station && !_plainFrames.Contains(l.Key)).OrderBy(l => l.Value)];
            ForgetLists(station);
            if (await ClearListsAsync(station, frames.Select(f => f.Value), cancellationToken).ConfigureAwait(false) is { } clearFailed)
            {
                return clearFailed;
            }
        }

        foreach (var (frameIndex, list) in frames)
        {
            var frame = _plan.Frames[frameIndex];
            var reply = await _link.ExchangeAsync(new DefineListRequest(station, list, frame.Items), cancellationToken).ConfigureAwait(false);
            CopyOf(frameIndex).Forget();
            switch (reply)
            {
                case LinkReply.Failed failed:
                    return failed;
                case LinkReply.Answered { Response: DefineListResponse }:
                    _definedFrames.Add(frameIndex);
                    break;
                default:
                    _plainFrames.Add(frameIndex);
                    _logger.Warning("{Station}: DEFINE LIST {List} ({Items}) not accepted ({Reply}); reading that frame with plain READ", station.Address, list, Describe(frame), Describe(reply.Response));
                    break;
            }
        }

        return null;
    }

    /// <summary>
    /// Empties the station's list tail: a DEFINE LIST of each id with one item past the end of V. A stored id clears
    /// every list before the item is refused (02); an id not stored is refused and changes nothing.
    /// </summary>
    private async Task<LinkReply.Failed?> ClearListsAsync(Station station, IEnumerable<int> lists, CancellationToken cancellationToken)
    {
        foreach (var list in lists)
        {
            if (await _link.ExchangeAsync(new DefineListRequest(station, list, [ClearingItem]), cancellationToken).ConfigureAwait(false) is LinkReply.Failed failed)
            {
                return failed;
            }
        }

        return null;
    }

    /// <summary>The handler cleared all of the station's lists and dropped their copies.</summary>
    private void ForgetLists(Station station)
    {
        foreach (var index in _listIds.Keys.Where(i => _plan.Frames[i].Station == station))
        {
            _definedFrames.Remove(index);
            CopyOf(index).Forget();
        }
    }

    private ListCopy CopyOf(int index)
    {
        if (!_copies.TryGetValue(index, out var copy))
        {
            copy = new ListCopy();
            _copies[index] = copy;
        }

        return copy;
    }

    private Task<LinkReply> ReadPlainAsync(PollFrame frame, CancellationToken cancellationToken) =>
        _link.ExchangeAsync(new ReadRequest(frame.Station, frame.Items), cancellationToken);
}
