using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Core.Polling;

/// <summary>
/// A bus as the project file describes it: the stations that share one serial port (one RS-485 bus). While connected,
/// each is a running Line/Bus with one link and one polling loop. The project file guarantees they share line settings
/// and have distinct station addresses.
/// </summary>
public sealed record ProjectBus(SerialSettings Serial, ImmutableArray<ProjectStation> Stations)
{
    /// <summary>The project's stations grouped by port, in the order the ports first appear.</summary>
    public static ImmutableArray<ProjectBus> Of(PanelProject project)
    {
        ArgumentNullException.ThrowIfNull(project);
        return [.. project.Stations
            .GroupBy(s => s.Link.PortName, StringComparer.OrdinalIgnoreCase)
            .Select(g => new ProjectBus(g.First().Link, [.. g]))];
    }

    /// <summary>Everything the panel shows of these stations: inputs, outputs, tags and alarm flags.</summary>
    public IEnumerable<WatchedItem> WatchedItems() =>
        Stations.SelectMany(s =>
            s.Inputs.Select(i => i.Address)
                .Concat(s.Outputs.Select(o => o.Address))
                .Concat(s.Tags.Select(t => t.Address))
                .Concat(s.Alarms.Select(a => a.Flag))
                .Select(address => new WatchedItem(s.Address, address)));

    /// <summary>What the bus reads per cycle: Freeport frames, or on a PPI bus one frame per S7 item (<see cref="PpiPollPlanner"/>).</summary>
    public PollPlan Plan(PollCostModel? costModel = null) => Plan(WatchedItems(), Stations.ToDictionary(s => s.Address, s => s.Cpu), costModel);

    /// <summary>The plan for <paramref name="items"/> on a bus of these line settings (a one-off read of <c>opanel</c>).</summary>
    public PollPlan Plan(IEnumerable<WatchedItem> items, IReadOnlyDictionary<Station, Cpu.CpuProfile>? cpus, PollCostModel? costModel = null) =>
        Serial.Protocol == LinkProtocol.Ppi ? PpiPollPlanner.Build(items, cpus) : PollPlanner.Build(items, cpus, costModel);

    public ProjectStation? StationAt(Station address) => Stations.FirstOrDefault(s => s.Address == address);
}
