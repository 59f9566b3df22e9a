namespace OperatorPanel.Cli.Watch;

/// <summary>What <c>opanel watch</c> shows at one moment: built first, then printed as text or one JSON line.</summary>
internal sealed record WatchSnapshot(string Project, string Refresh, long Cycle, DateTimeOffset Time, IReadOnlyList<StationSnapshot> Stations)
{
    public bool AllOffline => Stations.All(s => s.State != "online");
}
