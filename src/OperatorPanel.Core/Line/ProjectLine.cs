using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Audit;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Stop;
using OperatorPanel.Core.Writes;
using Serilog;
using Serilog.Core;

namespace OperatorPanel.Core.Line;

/// <summary>
/// A project's line. While connected, each <see cref="ProjectBus"/> (the stations on one serial port) has a transport
/// from the <see cref="ILineConnector"/>, a <see cref="PlcLink"/> over it and a <see cref="PollingEngine"/> looping on
/// the link (<see cref="BusLine"/>). A value travels one way: the transport's bytes → <see cref="PlcLink"/> (FrameReader,
/// ResponseCodec: the reply to the link's own sequence number) → <see cref="PollingEngine"/> (ValueStore: a
/// <see cref="ValueChange"/> batch per cycle) → this line, which routes each change by <see cref="WatchedItem"/> to the
/// <see cref="ILineValues"/> subscribers of that address only, through <see cref="ProjectLineOptions.Deliver"/> (the UI
/// dispatcher in the panel). The panel's session and <c>opanel watch</c> both open their line here. Connect, disconnect
/// and edits run on one thread (the UI thread in the panel); the loops run on their own.
/// </summary>
public sealed partial class ProjectLine : IAsyncDisposable
{
    private readonly ProjectLineOptions _options;
    private readonly TimeProvider _time;
    private readonly ILogger _logger;
    private readonly List<Bus> _buses = [];
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
    public IEnumerable<string> PortNames => _buses.Select(b => b.Line.Link.PortName);

    /// <summary>Switches the running engines at once; new engines start in it.</summary>
    public RefreshMode Mode
    {
        get => _mode;
        set
        {
            _mode = value;
            _buses.ForEach(b => b.Line.Engine.Mode = value);
        }
    }

    /// <summary>Opens the project's ports through <paramref name="connector"/> and starts polling every bus.</summary>
    public async Task ConnectAsync(ILineConnector connector, CancellationToken cancellationToken = default)
    {
        ArgumentNullException.ThrowIfNull(connector);
        if (IsConnected)
        {
            return;
        }

        var connection = await connector.ConnectAsync(Project, cancellationToken).ConfigureAwait(false);
        var resolved = new List<CutShortWrite>();
        foreach (var bus in ProjectBus.Of(Project))
        {
            var link = new PlcLink(connection.TransportFor(bus.Serial.PortName), _options.LinkOptionsFor(bus.Serial), _time, _logger);
            if (_options.Journal is { } journal)
            {
                resolved.AddRange((await UnfinishedWrites.ResolveAsync(journal, link, link.PortName, _time, _logger, cancellationToken).ConfigureAwait(false)).Resolved);
            }

            _buses.Add(new Bus(bus, Start(bus, link)));
        }

        ResolvedAtConnect = resolved;

        _connection = connection;
        PushAll();
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
            await bus.Line.DisposeAsync().ConfigureAwait(false);
        }

        // The connector's own parts stop before the ports close, or they would see an unplugged line.
        await connection.DisposeAsync().ConfigureAwait(false);
        foreach (var bus in _buses)
        {
            await bus.Line.Link.DisposeAsync().ConfigureAwait(false);
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
    /// each bus whose watch list changed gets a new engine on its open link (the link and its counters carry over). A
    /// changed set of ports or stations (<see cref="SameStations"/> false) needs other ports: disconnect first.
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
                await old.Line.DisposeAsync().ConfigureAwait(false);
                _buses[i] = new Bus(buses[i], Start(buses[i], old.Line.Link));
            }
        }

        PushAll();
    }

    /// <summary>One full cycle of every bus: on demand the only way values change; in continuous mode the next regular cycle.</summary>
    public Task RefreshAsync(CancellationToken cancellationToken = default) =>
        Task.WhenAll(_buses.Select(b => b.Line.Engine.RequestRefreshAsync(cancellationToken)));

    /// <summary>
    /// Writes through the station's engine; the outcome is the PLC's read-back, never the request. The write's record
    /// names the address's symbol in the project when the request does not.
    /// </summary>
    public Task<WriteOutcome> WriteAsync(WriteRequest request, CancellationToken cancellationToken = default)
    {
        ArgumentNullException.ThrowIfNull(request);
        request = request.Symbol is null ? request with { Symbol = Project.Stations.FirstOrDefault(s => s.Address == request.Station)?.SymbolOf(request.Address) } : request;
        return BusOf(request.Station) is { } bus
            ? bus.Line.Engine.WriteAsync(request, cancellationToken)
            : Task.FromResult<WriteOutcome>(new WriteOutcome.Failed($"{request.Address}: not connected, nothing written", WriteFailureKind.InvalidRequest));
    }

    /// <summary>
    /// IDENTIFY to one station, beside the polling (one request on the wire at a time). The engine hears the reply: a
    /// handler without READ CHANGES copies gets its lists read with READ LIST.
    /// </summary>
    public Task<PlcResponse> IdentifyAsync(Station station, CancellationToken cancellationToken = default) =>
        BusOf(station) is { } bus
            ? IdentifyOnAsync(bus, station, cancellationToken)
            : throw new InvalidOperationException($"{station} is not on a connected bus");

    /// <summary>
    /// STOP to one station beside the polling (<see cref="RemoteStop"/>: IDENTIFY, 07 once, IDENTIFY). A STOP that left
    /// the station silent tells its engine, which then shows it as stopped by the panel instead of offline.
    /// </summary>
    public async Task<StopOutcome> StopAsync(Station station, CancellationToken cancellationToken = default)
    {
        if (BusOf(station) is not { } bus)
        {
            return new StopOutcome.NotSent(station, "not connected");
        }

        var outcome = await new RemoteStop(bus.Line.Link, _logger, AuditFor(bus.Line.Link)).StopAsync(station, cancellationToken).ConfigureAwait(false);
        if (outcome.IsStopped)
        {
            bus.Line.Engine.NoteStoppedByPanel(station);
        }

        return outcome;
    }

    /// <summary>The station's polling status; null when not connected.</summary>
    public StationStatus? StatusOf(Station station) => BusOf(station)?.Line.Engine.GetStationStatus(station);

    public LinkStatistics StatisticsFor(Station station) => BusOf(station)?.Line.Link.StatisticsFor(station) ?? LinkStatistics.Empty;

    /// <summary>The port the station is reached on while connected.</summary>
    public string? PortOf(Station station) => BusOf(station)?.Line.Link.PortName;

    public async ValueTask DisposeAsync() => await DisconnectAsync().ConfigureAwait(false);

    private AuditContext? AuditFor(PlcLink link) =>
        (_options.Audit ?? _options.Journal) is { } trail ? new AuditContext(trail, link.PortName, AuditUser.Current) : null;

    private BusLine Start(ProjectBus bus, PlcLink link)
    {
        var line = BusLine.Start(link, bus.Plan(), Mode, Project.Refresh.MinimumPeriod, _options.UseReadLists, _time, _logger, AuditFor(link));
        line.Engine.Subscribe(OnEngineChanges);
        return line;
    }

    private static async Task<PlcResponse> IdentifyOnAsync(Bus bus, Station station, CancellationToken cancellationToken)
    {
        var reply = await bus.Line.Link.ExchangeAsync(new IdentifyRequest(station), cancellationToken).ConfigureAwait(false);
        if (reply is IdentifyResponse identity)
        {
            bus.Line.Engine.NoteIdentity(identity);
        }

        return reply;
    }

    private Bus? BusOf(Station station) => _buses.FirstOrDefault(b => b.Project.StationAt(station) is not null);

    /// <summary>True when <paramref name="b"/> keeps <paramref name="a"/>'s stations, CPUs and ports: an edit the running line can follow.</summary>
    public static bool SameStations(PanelProject a, PanelProject b) =>
        a.Stations.Select(s => (s.Name, s.Address, s.Cpu, s.Link)).SequenceEqual(b.Stations.Select(s => (s.Name, s.Address, s.Cpu, s.Link)));

    /// <summary>A bus of the project and, while connected, its running line.</summary>
    private sealed record Bus(ProjectBus Project, BusLine Line);
}
