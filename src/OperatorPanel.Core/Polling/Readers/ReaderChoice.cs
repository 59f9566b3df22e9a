using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Writes;

namespace OperatorPanel.Core.Polling.Readers;

/// <summary>
/// How the polling loop reads and writes the stations of one bus: the bus's <see cref="Writer"/>, and the readers of
/// each station of the plan, in the order the loop asks them, chosen from what the station reported in IDENTIFY (docs/protocol.md, "01 IDENTIFY", FEATURES): until it has, <see cref="ListReader"/> with READ CHANGES;
/// without READ CHANGES copies (FEATURES bit 1 clear or COPY_BYTES 0) every READ CHANGES would answer FULL, 4 characters
/// longer than READ LIST, so its lists are read with READ LIST; with FEATURES bit 2 the lists in step go first in one
/// <see cref="ChangesOfListsReader"/> exchange. <see cref="PlainReader"/> is last for every station. A PPI bus
/// (<see cref="PollingContext.Ppi"/>) reads every station with <see cref="PpiReader"/> and writes with
/// <see cref="PpiWriter"/>; a v3 bus (<see cref="PollingContext.V3"/>) reads as <see cref="V3ReaderChoice"/> says. The place where a new way of reading is chosen (docs/architecture.md, "Readers").
/// </summary>
internal sealed class ReaderChoice
{
    private readonly PollingContext _context;
    private readonly Lock _gate = new();
    private readonly Dictionary<Station, StoredLists> _lists = [];
    private readonly Dictionary<Station, ImmutableArray<IStationReader>> _readers = [];
    private readonly V3ReaderChoice? _v3;

    public ReaderChoice(PollingContext context)
    {
        ArgumentNullException.ThrowIfNull(context);
        _context = context;
        _v3 = context.V3 is { } v3 ? new V3ReaderChoice(context, v3) : null;
        Writer = context.Ppi is { } ppi ? new PpiWriter(context, ppi) : new FreeportWriter(context);
        foreach (var station in context.Plan.Stations)
        {
            _lists[station] = new StoredLists(context.Plan, station);
            _readers[station] = Choose(_lists[station], identity: null);
        }
    }

    /// <summary>How writes reach the bus's stations: the handler's WRITE and WRITE BIT, or S7 write-var on a PPI bus.</summary>
    public IStationWriter Writer { get; }

    public ImmutableArray<IStationReader> ReadersOf(Station station)
    {
        lock (_gate)
        {
            return _readers[station];
        }
    }

    /// <summary>Chooses the station's readers again from its IDENTIFY reply; they read from the next exchange on.</summary>
    public void NoteIdentity(IdentifyResponse identity)
    {
        ArgumentNullException.ThrowIfNull(identity);
        lock (_gate)
        {
            if (_lists.TryGetValue(identity.Station, out var lists))
            {
                _readers[identity.Station] = Choose(lists, identity);
            }
        }
    }

    private ImmutableArray<IStationReader> Choose(StoredLists lists, IdentifyResponse? identity)
    {
        if (_context.Ppi is { } ppi)
        {
            // A PPI bus: no handler, so no IDENTIFY to choose from; every station is read with S7 jobs.
            return [new PpiReader(_context, ppi)];
        }

        if (_v3 is { } v3)
        {
            // A v3 bus: the writer above works through the link's IPlcLink face; reading has its own readers.
            return v3.Choose(lists.Station);
        }

        var plain = new PlainReader(_context);
        if (!_context.Options.UseReadLists || lists.Lists.IsEmpty)
        {
            return [plain];
        }

        var readsChanges = _context.Options.UseReadChanges && (identity is null || (identity.HasCopies && identity.CopyBytes > 0));
        var stored = new ListReader(_context, lists, readsChanges);
        return readsChanges && identity is { HasChangesOfLists: true }
            ? [new ChangesOfListsReader(_context, lists, stored), stored, plain]
            : [stored, plain];
    }
}
