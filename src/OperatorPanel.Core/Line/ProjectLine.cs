using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Audit;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Link.V3;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Ppi;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Stop;
using OperatorPanel.Core.Transport;
using OperatorPanel.Core.Writes;
using Serilog;
using Serilog.Core;

namespace OperatorPanel.Core.Line;

/// <summary>
/// A project's line: its buses. While connected, each <see cref="ProjectBus"/> (the stations on one serial port) is a
/// running <see cref="Bus"/> over a transport from the <see cref="ILineConnector"/>. A value travels one way: the
/// transport's bytes → <see cref="V3Link"/> (protocol v3: Protocol/V3's Reader cuts frames by LEN, Codec takes the reply
/// whose REQCHECK is the request's) → the bus's polling loop (a reader per way of reading, ValueStore: a <see cref="ValueChange"/> batch per cycle) → this
/// line, which routes each change by <see cref="WatchedItem"/> to the <see cref="ILineValues"/> subscribers of that
/// address only, through <see cref="ProjectLineOptions.Deliver"/> (the UI dispatcher in the panel); docs/architecture.md
/// walks it hop by hop. The panel's session and <c>opanel watch</c> both open their line here. Connect, disconnect and
/// edits run on one thread (the UI thread in the panel); the loops run on their own.
/// </summary>
public sealed partial class ProjectLine : IAsyncDisposable
{
    private readonly ProjectLineOptions _options;
    private readonly TimeProvider _time;
    private readonly ILogger _logger;
    private readonly List<LineBus> _buses = [];
    private LineConnection? _connection;
    private RefreshMode _mode;

    public ProjectLine(PanelProject project, ProjectLineOptions? options = null, TimeProvider? time = null, ILogger? logger = null)
    {
        ArgumentNullException.ThrowIfNull(project);
        Project = project;
        _mode = project.Refresh.Mode;
        _options = options ?? new ProjectLineOptions();
        _time = time ?? TimeProvider.System;
        _logger = (logger ?? Logger.None).ForContext<ProjectLine>();
    }

    public PanelProject Project { get; private set; }

    public bool IsConnected => _connection is not null;

    /// <summary>Writes and STOPs of earlier programs on these ports, cut short and settled on the last connect (resolved at start).</summary>
    public IReadOnlyList<CutShortWrite> ResolvedAtConnect { get; private set; } = [];

    /// <summary>The ports in use while connected ("COM3", "COM7 (demo)").</summary>
    public IEnumerable<string> PortNames => _buses.Select(b => b.Bus.PortName);

    /// <summary>Switches the running buses at once; new buses start in it.</summary>
    public RefreshMode Mode
    {
        get => _mode;
        set
        {
            _mode = value;
            _buses.ForEach(b => b.Bus.Mode = value);
        }
    }

    /// <summary>
    /// Opens the project's ports through <paramref name="connector"/> and starts polling every bus; with a write journal,
    /// each bus first settles the writes its port's earlier programs left cut short (<see cref="ResolvedAtConnect"/>).
    /// </summary>
    public async Task ConnectAsync(ILineConnector connector, CancellationToken cancellationToken = default)
    {
        ArgumentNullException.ThrowIfNull(connector);
        if (IsConnected)
        {
            return;
        }

        var connection = await connector.ConnectAsync(Project, cancellationToken).ConfigureAwait(false);
        foreach (var bus in ProjectBus.Of(Project))
        {
            var transport = connection.TransportFor(bus.Serial.PortName);
            var options = _options.LinkOptionsFor(bus.Serial);
            options = options with { ScanAllowance = options.ScanAllowance + connection.ScanAllowance };
            var settings = new BusSettings
            {
                Mode = Mode,
                MinimumPeriod = Project.Refresh.MinimumPeriod,
                Polling = new PollingOptions { UseReadLists = _options.UseReadLists },
                Audit = _options.Audit ?? _options.Journal,
            };
            var running = bus.Serial.Protocol == LinkProtocol.Ppi
                ? Bus.StartPpi(new PpiLink(transport, _options.PpiOptionsFor(bus.Serial), _time, _logger), bus.Plan(), settings, _time, _logger, OnBusChanges)
                : Bus.StartV3(new V3Link(transport, options, _time, _logger), bus.Plan(), settings, _time, _logger, OnBusChanges);
            _buses.Add(new LineBus(bus, running));
        }

        _connection = connection;
        PushAll();
        ResolvedAtConnect = _options.Journal is { } journal ? await SettleCutShortAsync(journal, cancellationToken).ConfigureAwait(false) : [];
    }

    /// <summary>Each bus settles, through its queue and ahead of any write, what earlier programs left cut short on its port.</summary>
    private async Task<IReadOnlyList<CutShortWrite>> SettleCutShortAsync(WriteJournal journal, CancellationToken cancellationToken)
    {
        var settled = await Task.WhenAll(_buses.Select(b => b.Bus.SettleCutShortAsync(journal, cancellationToken))).ConfigureAwait(false);
        return [.. settled.SelectMany(s => s.Resolved)];
    }

    /// <summary>Stops the loops, then what the connector runs beside the ports (a demo line), then closes the ports.</summary>
    public async Task DisconnectAsync()
    {
        if (_connection is not { } connection)
        {
            return;
        }

        foreach (var bus in _buses)
        {
            await bus.Bus.StopPollingAsync().ConfigureAwait(false);
        }

        // The connector's own parts stop before the ports close, or they would see an unplugged line.
        await connection.DisposeAsync().ConfigureAwait(false);
        foreach (var bus in _buses)
        {
            await bus.Bus.DisposeAsync().ConfigureAwait(false);
        }

        _buses.Clear();
        _connection = null;
        PushAll();
    }

    /// <summary>Takes another project; disconnect first, the open ports belong to the old one.</summary>
    public void Load(PanelProject project)
    {
        ArgumentNullException.ThrowIfNull(project);
        if (IsConnected)
        {
            throw new InvalidOperationException("disconnect before loading another project");
        }

        Project = project;
        Mode = project.Refresh.Mode;
        PushAll();
    }

    /// <summary>
    /// Takes an edited version of the same project (memory cells added, removed, moved, reformatted). While connected,
    /// each bus whose watch list changed polls its new plan on its open port (<see cref="Bus.WatchAsync"/>: the link, its
    /// counters, the station states and what IDENTIFY said carry over). A changed set of ports or stations
    /// (<see cref="SameStations"/> false) needs other ports: disconnect first.
    /// </summary>
    public async Task EditAsync(PanelProject edited)
    {
        ArgumentNullException.ThrowIfNull(edited);
        if (IsConnected && !SameStations(Project, edited))
        {
            throw new InvalidOperationException("the edit changes ports or stations: disconnect before applying it");
        }

        Project = edited;
        if (!IsConnected)
        {
            PushAll();
            return;
        }

        var buses = ProjectBus.Of(edited);
        for (var i = 0; i < _buses.Count; i++)
        {
            var old = _buses[i];
            if (!old.Project.WatchedItems().SequenceEqual(buses[i].WatchedItems()))
            {
                await old.Bus.WatchAsync(buses[i].Plan()).ConfigureAwait(false);
            }

            _buses[i] = old with { Project = buses[i] };
        }

        PushAll();
    }

    /// <summary>One full cycle of every bus now ("Refresh now"): on demand the only way values change; in continuous mode it does not wait out the minimum period.</summary>
    public Task RefreshAsync(CancellationToken cancellationToken = default) =>
        Task.WhenAll(_buses.Select(b => b.Bus.RefreshAsync(cancellationToken)));

    /// <summary>
    /// Waits for the next cycle of every bus without asking for one: in continuous mode the next regular cycle (the
    /// project's minimum period holds), in triggered mode one asked for now.
    /// </summary>
    public Task NextCycleAsync(CancellationToken cancellationToken = default) =>
        Task.WhenAll(_buses.Select(b => b.Bus.NextCycleAsync(cancellationToken)));

    /// <summary>
    /// Writes through the station's bus; the outcome is the PLC's read-back, never the request. The write's record names
    /// the address's symbol in the project when the request does not.
    /// </summary>
    public Task<WriteOutcome> WriteAsync(WriteRequest request, CancellationToken cancellationToken = default)
    {
        ArgumentNullException.ThrowIfNull(request);
        request = request.Symbol is null ? request with { Symbol = Project.Stations.FirstOrDefault(s => s.Address == request.Station)?.SymbolOf(request.Address) } : request;
        return BusOf(request.Station) is { } bus
            ? bus.WriteAsync(request, cancellationToken)
            : Task.FromResult<WriteOutcome>(new WriteOutcome.Failed($"{request.Address}: not connected, nothing written", WriteFailureKind.InvalidRequest));
    }

    /// <summary>
    /// IDENTIFY to one station through its bus's queue. What the reply says chooses how its lists are read (READ LIST
    /// for a handler without READ CHANGES copies, one 09 for the lists in step with FEATURES bit 2).
    /// </summary>
    public Task<LinkReply> IdentifyAsync(Station station, CancellationToken cancellationToken = default) =>
        BusOf(station) is { } bus
            ? bus.IdentifyAsync(station, cancellationToken)
            : throw new InvalidOperationException($"{station} is not on a connected bus");

    /// <summary>
    /// STOP to one station through its bus's queue (<see cref="RemoteStop"/>: IDENTIFY, 07 once, IDENTIFY). A STOP that
    /// left the station silent shows it as stopped by the panel instead of offline.
    /// </summary>
    public Task<StopOutcome> StopAsync(Station station, CancellationToken cancellationToken = default) =>
        BusOf(station) is { } bus
            ? bus.StopAsync(station, cancellationToken)
            : Task.FromResult<StopOutcome>(new StopOutcome.NotSent(station, "not connected"));

    /// <summary>What PPI tells about a station of a PPI bus (SMB6, SM0.7, scan times), through its bus's queue.</summary>
    public Task<PpiIdentifyOutcome> IdentifyPpiAsync(Station station, CancellationToken cancellationToken = default) =>
        BusOf(station) is { } bus
            ? bus.IdentifyPpiAsync(station, cancellationToken)
            : throw new InvalidOperationException($"{station} is not on a connected bus");

    /// <summary>What the station said in its last answered IDENTIFY while connected; null before one answered or when not connected.</summary>
    public IdentifyResponse? IdentityOf(Station station) => BusOf(station)?.IdentityOf(station);

    /// <summary>What the station's last IDENTIFY brought (its reply or the failure); null before any or when not connected.</summary>
    public LinkReply? LastIdentifyOf(Station station) => BusOf(station)?.LastIdentifyOf(station);

    /// <summary>The station's polling status; null when not connected.</summary>
    public StationStatus? StatusOf(Station station) => BusOf(station)?.StatusOf(station);

    public LinkStatistics StatisticsFor(Station station) => BusOf(station)?.StatisticsFor(station) ?? LinkStatistics.Empty;

    /// <summary>The port the station is reached on while connected.</summary>
    public string? PortOf(Station station) => BusOf(station)?.PortName;

    public async ValueTask DisposeAsync() => await DisconnectAsync().ConfigureAwait(false);

    private Bus? BusOf(Station station) => _buses.FirstOrDefault(b => b.Project.StationAt(station) is not null)?.Bus;

    /// <summary>True when <paramref name="b"/> keeps <paramref name="a"/>'s stations, CPUs and ports: an edit the running line can follow.</summary>
    public static bool SameStations(PanelProject a, PanelProject b) =>
        a.Stations.Select(s => (s.Name, s.Address, s.Cpu, s.Link)).SequenceEqual(b.Stations.Select(s => (s.Name, s.Address, s.Cpu, s.Link)));

    /// <summary>A bus of the project and, while connected, the running bus.</summary>
    private sealed record LineBus(ProjectBus Project, Bus Bus);
}
