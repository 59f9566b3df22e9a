using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Link.V3;
using OperatorPanel.Core.Protocol.V3;

namespace OperatorPanel.Core.Polling.Readers;

/// <summary>
/// The readers of a v3 bus's station (<see cref="ReaderChoice"/> asks this when <see cref="PollingContext.V3"/> is set),
/// from the station's v3 IDENTIFY (<see cref="V3Link.IdentityOf"/>): a handler with the list feature gets
/// <see cref="V3ListReader"/> sized by its LIST_ITEMS and LIST_BYTES, then <see cref="V3ReadReader"/> for the frames that
/// do not fit; a compact one READ only. Before the bus's IDENTIFY answered, the list reader asks IDENTIFY itself before
/// its first DEFINE LIST (a compact handler is silent to a request longer than its buffer, so the PC must know the
/// shape first). A station's list state survives a new IDENTIFY that reports the same shape, as the station keeps its list.
/// </summary>
internal sealed class V3ReaderChoice(PollingContext context, V3Link link)
{
    private readonly Dictionary<Station, V3StationList> _lists = [];

    public ImmutableArray<IStationReader> Choose(Station station)
    {
        var identity = link.IdentityOf(station);
        var read = new V3ReadReader(context, identity is { MaxData: > 0 } ? identity.MaxData : HandlerShape.MaxData);
        return !context.Options.UseReadLists || identity is { HasList: false } ? [read] : [new V3ListReader(context, link, this, station), read];
    }

    /// <summary>The station's list for a handler of <paramref name="identity"/>'s shape: the one kept while the shape stays.</summary>
    public V3StationList ListFor(Station station, Identity identity)
    {
        ArgumentNullException.ThrowIfNull(identity);
        var shape = new HandlerShape(identity.MaxRequestBytes, identity.ListItems, identity.ListBytes);
        lock (_lists)
        {
            if (!_lists.TryGetValue(station, out var list) || list.Shape != shape)
            {
                list = _lists[station] = new V3StationList(context.Plan, station, shape, identity.AreaBytes);
            }

            return list;
        }
    }
}
