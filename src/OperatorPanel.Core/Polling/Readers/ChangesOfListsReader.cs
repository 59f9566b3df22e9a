using System.Collections.Immutable;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Core.Polling.Readers;

/// <summary>
/// 09 READ CHANGES OF LISTS (docs/protocol-v2.md section 2, its PC rules 1-5), chosen for a station whose IDENTIFY has
/// FEATURES bit 2: every list in step (an 08 without FULL would be allowed) is read with ONE 09 before the station's other
/// frames. The lists due a FULL, and every list of the mask the 09 did not bring (a REREAD entry, a 09 without a good
/// reply, a reply whose INDEX lies past a list's data), are left to <see cref="ListReader"/>, which reads them with 08
/// FULL in the same cycle, so the cycle's values stay complete. A 09 is never repeated. A list answered REREAD although
/// nothing changed has no copy in the handler: like a list answered FULL unasked it is read with READ LIST until its next
/// periodic FULL. A handler that refuses the 09 itself is read with 08 until its next IDENTIFY chooses readers again.
/// </summary>
internal sealed class ChangesOfListsReader(PollingContext context, StoredLists lists, ListReader changes) : IStationReader
{
    private bool _refused;

    public async Task<IReadOnlyList<(int Frame, FrameRead Read)>> ReadAsync(IReadOnlyList<int> pending, CancellationToken cancellationToken)
    {
        ArgumentNullException.ThrowIfNull(pending);
        var inStep = InStep(pending);
        if (inStep.Count == 0)
        {
            return [];
        }

        var station = lists.Station;
        var names = string.Join(", ", inStep.Select(l => l.List));
        var request = new ReadChangesOfListsRequest(station, ReadChangesOfListsRequest.MaskOf(inStep.Select(l => l.List)));
        var reply = await context.Link.ExchangeAsync(request, cancellationToken).ConfigureAwait(false);
        if (reply.Failure is { } failure)
        {
            // The lost reply may have moved the PLC's copies on: never repeat the 09, read each list with 08 FULL (rule 2).
            Forget(inStep);
            context.Logger.Debug("{Station}: READ CHANGES OF LISTS {Lists} brought no reply ({Error}); asking each FULL", station.Address, names, failure.Message);
            return [];
        }

        if (reply.Response is ReadChangesOfListsResponse entries && Apply(inStep, entries) is { } applied)
        {
            // The station answered, whatever each entry says: REREAD entries too.
            context.Judge.Stations.RecordReply(station);
            return [.. applied.Select(a => (a.Key, FrameRead.Success(a.Value)))];
        }

        Forget(inStep);
        switch (reply.Response)
        {
            case ErrorResponse { Error: ProtocolError.ListNotDefined }:
                // The station lost its lists (and their copies); ListReader defines them again and reads them with 08 FULL.
                lists.ForgetAll();
                context.Logger.Debug("{Station}: lists {Lists} not defined (invalidated); defining the station's lists again", station.Address, names);
                break;
            case ErrorResponse refused:
                // The REQCHECK matched, so the handler refused exactly this frame and would again: 08 from now on.
                _refused = true;
                context.Logger.Warning("{Station} refused READ CHANGES OF LISTS {Lists} ({Error}); reading its lists with READ CHANGES until its next IDENTIFY", station.Address, names, refused.Error);
                break;
            default:
                context.Judge.Stations.RecordBadReply(station, $"unexpected reply to READ CHANGES OF LISTS {names}: {FrameJudge.Describe(reply.Response)}; asking each FULL");
                break;
        }

        return [];
    }

    /// <summary>
    /// The pending lists that may go in a 09 mask (rule 1), in id order: the handler did not refuse 09 (rule 5), the list
    /// is defined, read with READ CHANGES (not in a READ LIST spell) and in step.
    /// </summary>
    private List<(int Frame, int List)> InStep(IReadOnlyList<int> pending)
    {
        if (_refused)
        {
            return [];
        }

        var now = context.Time.GetUtcNow();
        return [.. lists.Stored.Where(l => pending.Contains(l.Frame) && lists.IsDefined(l.Frame)
            && changes.ReadsChanges(l.Frame, now) && lists.CopyOf(l.Frame).InStep(now, context.Options.FullReadInterval))];
    }

    /// <summary>
    /// Every entry applied to its list's copy, by frame index; a REREAD entry's list is left out and its copy forgotten,
    /// so it is read with 08 FULL (rule 3). Null, and nothing applied, when an entry does not answer the list it stands
    /// for or a change's INDEX lies at or past its list's data (rule 4: the whole reply is dropped).
    /// </summary>
    private Dictionary<int, ImmutableArray<byte>>? Apply(List<(int Frame, int List)> inStep, ReadChangesOfListsResponse reply)
    {
        if (!reply.Lists.Select(e => e.List).SequenceEqual(inStep.Select(l => l.List)))
        {
            return null;
        }

        var applied = new Dictionary<int, ImmutableArray<byte>>();
        foreach (var ((index, _), entry) in inStep.Zip(reply.Lists))
        {
            if (entry.Reread)
            {
                continue;
            }

            if (!entry.TryApply(lists.CopyOf(index).Data.AsSpan(), out var data))
            {
                return null;
            }

            applied[index] = data;
        }

        foreach (var ((index, list), entry) in inStep.Zip(reply.Lists))
        {
            var copy = lists.CopyOf(index);
            if (entry.Reread)
            {
                copy.BeforeReread = copy.Data;
                copy.Forget();
                context.Logger.Debug("{Station}: list {List} answered REREAD in READ CHANGES OF LISTS; asking it FULL", reply.Station.Address, list);
            }
            else
            {
                copy.Data = applied[index];
            }
        }

        return applied;
    }

    private void Forget(List<(int Frame, int List)> inStep) => inStep.ForEach(l => lists.CopyOf(l.Frame).Forget());
}
