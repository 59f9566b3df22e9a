using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Core.Polling;

/// <summary>
/// 09 READ CHANGES OF LISTS (docs/protocol.md section 2, its PC rules 1-5): for a station whose IDENTIFY has FEATURES
/// bit 2, every list in step (an 08 without FULL would be allowed) is read with ONE 09 before the station's other
/// frames. The lists due a FULL, and every list of the mask the 09 did not bring (a REREAD entry, a 09 without a good
/// reply, a reply whose INDEX lies past a list's data), go the 08 way in the same cycle with FULL, so the cycle's values
/// stay complete. A 09 is never repeated. A list answered REREAD although nothing changed has no copy in the handler:
/// like a list answered FULL unasked it is read with READ LIST until its next periodic FULL. Without bit 2 every list
/// is read with 08 as before.
/// </summary>
public sealed partial class PollingEngine
{
    private readonly HashSet<Station> _stationsWithChangesOfLists = [];

    /// <summary>
    /// Reads the station's lists in step with one 09 and puts what it brought into <paramref name="reads"/>; returns the
    /// frame indexes it served (none when no list is in step or the 09 brought no good reply).
    /// </summary>
    private async Task<IReadOnlySet<int>> ReadChangesOfListsAsync(Station station, FrameRead[] reads, CancellationToken cancellationToken)
    {
        var lists = ListsInStep(station);
        if (lists.Count == 0)
        {
            return ImmutableHashSet<int>.Empty;
        }

        var request = new ReadChangesOfListsRequest(station, ReadChangesOfListsRequest.MaskOf(lists.Select(l => l.List)));
        var names = string.Join(", ", lists.Select(l => l.List));
        var exchange = await _link.ExchangeAsync(request, cancellationToken).ConfigureAwait(false);
        if (exchange.Failure is { } failure)
        {
            // The lost reply may have moved the PLC's copies on: never repeat the 09, read each list with 08 FULL (rule 2).
            ForgetCopies(lists);
            _logger.Debug("{Station}: READ CHANGES OF LISTS {Lists} brought no reply ({Error}); asking each FULL", station.Address, names, failure.Message);
            return ImmutableHashSet<int>.Empty;
        }

        var response = exchange.Response;
        if (response is ReadChangesOfListsResponse reply && Apply(lists, reply) is { } applied)
        {
            _stations.RecordReply(station);
            foreach (var (index, data) in applied)
            {
                reads[index] = FrameRead.Success(data);
            }

            return applied.Keys.ToHashSet();
        }

        ForgetCopies(lists);
        switch (response)
        {
            case ErrorResponse { Error: ProtocolError.ListNotDefined }:
                // The station lost its lists (and their copies); the frames define them again and read them with 08 FULL.
                ForgetLists(station);
                _logger.Debug("{Station}: lists {Lists} not defined (invalidated); defining the station's lists again", station.Address, names);
                break;
            case ErrorResponse refused:
                // The REQCHECK matched, so the handler refused exactly this frame and would again: 08 from now on.
                lock (_gate) { _stationsWithChangesOfLists.Remove(station); }
                _logger.Warning("{Station} refused READ CHANGES OF LISTS {Lists} ({Error}); reading its lists with READ CHANGES until its next IDENTIFY", station.Address, names, refused.Error);
                break;
            default:
                _stations.RecordBadReply(station, $"unexpected reply to READ CHANGES OF LISTS {names}: {Describe(response)}; asking each FULL");
                break;
        }

        return ImmutableHashSet<int>.Empty;
    }

    /// <summary>
    /// The station's lists that may go in a 09 mask (rule 1), in id order: the handler answers 09 (rule 5), the list is
    /// defined, read with READ CHANGES (not in a READ LIST spell) and in step.
    /// </summary>
    private List<(int Index, int List)> ListsInStep(Station station)
    {
        bool answers09;
        lock (_gate) { answers09 = _stationsWithChangesOfLists.Contains(station); }
        if (!UseReadLists || !answers09)
        {
            return [];
        }

        var now = _time.GetUtcNow();
        return [.. _listIds
            .Where(l => _plan.Frames[l.Key].Station == station && _definedFrames.Contains(l.Key) && !_plainFrames.Contains(l.Key))
            .Where(l => ReadsChanges(l.Key, now) && CopyOf(l.Key).InStep(now, Options.FullReadInterval))
            .OrderBy(l => l.Value)
            .Select(l => (l.Key, l.Value))];
    }

    /// <summary>
    /// Every entry applied to its list's copy, by frame index; a REREAD entry's list is left out and its copy forgotten,
    /// so the frame reads it with 08 FULL (rule 3). Null, and nothing applied, when an entry does not answer the list it
    /// stands for or a change's INDEX lies at or past its list's data (rule 4: the whole reply is dropped).
    /// </summary>
    private Dictionary<int, ImmutableArray<byte>>? Apply(List<(int Index, int List)> lists, ReadChangesOfListsResponse reply)
    {
        if (!reply.Lists.Select(e => e.List).SequenceEqual(lists.Select(l => l.List)))
        {
            return null;
        }

        var applied = new Dictionary<int, ImmutableArray<byte>>();
        foreach (var ((index, _), entry) in lists.Zip(reply.Lists))
        {
            if (entry.Reread)
            {
                continue;
            }

            if (!entry.TryApply(CopyOf(index).Data.AsSpan(), out var data))
            {
                return null;
            }

            applied[index] = data;
        }

        foreach (var ((index, list), entry) in lists.Zip(reply.Lists))
        {
            if (entry.Reread)
            {
                CopyOf(index).BeforeReread = CopyOf(index).Data;
                CopyOf(index).Forget();
                _logger.Debug("{Station}: list {List} answered REREAD in READ CHANGES OF LISTS; asking it FULL", reply.Station.Address, list);
            }
            else
            {
                CopyOf(index).Data = applied[index];
            }
        }

        return applied;
    }

    private void ForgetCopies(List<(int Index, int List)> lists) => lists.ForEach(l => CopyOf(l.Index).Forget());
}
