using System.Collections.Concurrent;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Audit;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Link.V3;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Ppi;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Stop;
using OperatorPanel.Core.Writes;
using Serilog;

namespace OperatorPanel.Core.Line;

/// <summary>
/// One bus: one serial port and the stations on it, while connected. The one owner of everything on that wire: the
/// transport (through its <see cref="PlcLink"/>), the station states, what each station reported in IDENTIFY, and the
/// polling loop (Polling/PollingEngine) running on the link. Polling, writes, IDENTIFY and STOP all pass through its one
/// queue (Polling/BusQueue, S7NetPlus's TaskQueue idea), which the loop drains between two of its exchanges: one request
/// is on the wire at a time by that one mechanism. With an audit trail (<see cref="BusSettings.Audit"/>) every write and
/// STOP is on record before its frame leaves and its outcome before the caller hears it. Front ends reach a bus through the line (<see cref="ProjectLine"/>) or,
/// for one verb of <c>opanel</c>, directly. Disposing stops the loop (after its exchange on the wire) and closes the port.
/// A bus that speaks PPI (<see cref="StartPpi"/>) owns a <see cref="PpiLink"/> instead of a Freeport link; its loop reads
/// and writes with the PPI reader and writer, and the same queue keeps one job on its wire (docs/ppi.md, "The panel over PPI").
/// </summary>
public sealed class Bus : IAsyncDisposable
{
    private readonly IPlcLink _link;
    private readonly PpiLink? _ppi;
    private readonly V3Link? _v3;
    private readonly IAsyncDisposable _wire;
    private readonly BusSettings _settings;
    private readonly TimeProvider _time;
    private readonly ILogger _logger;
    private readonly StationTracker _stations;
    private readonly BusQueue _queue;
    private readonly ConcurrentDictionary<Station, IdentifyResponse> _identities = new();
    private readonly ConcurrentDictionary<Station, LinkReply> _lastIdentify = new();
    private readonly Action<IReadOnlyList<ValueChange>> _onChanges;
    private readonly AuditContext? _audit;
    private PollingEngine _engine;
    private CancellationTokenSource _stop = new();
    private Task _loop = Task.CompletedTask;
    private bool _polling;

    private Bus(IPlcLink link, PpiLink? ppi, V3Link? v3, string portName, IAsyncDisposable wire, PollPlan plan, BusSettings settings, TimeProvider time, ILogger logger, Action<IReadOnlyList<ValueChange>>? onChanges)
    {
        (_link, _ppi, _v3, PortName, _wire, _settings, _time, _logger) = (link, ppi, v3, portName, wire, settings, time, logger);
        _stations = new StationTracker(time, logger.ForContext<PollingEngine>());
        _queue = new BusQueue(logger.ForContext<Bus>());
        _onChanges = onChanges ?? (_ => { });
        _audit = settings.Audit is { } trail ? new AuditContext(trail, portName, AuditUser.Current) : null;
        _engine = NewEngine(plan, settings.Mode);
        StartLoop();
    }

    /// <summary>
    /// Starts polling <paramref name="plan"/> on <paramref name="link"/>, which the bus owns from now on.
    /// <paramref name="onChanges"/> hears, on the loop's thread, the changed values after every cycle and every job, an
    /// empty batch included (Line/ProjectLine routes them to the subscribers of each address and raises StateChanged).
    /// </summary>
    public static Bus Start(PlcLink link, PollPlan plan, BusSettings settings, TimeProvider? time = null, ILogger? logger = null, Action<IReadOnlyList<ValueChange>>? onChanges = null)
    {
        ArgumentNullException.ThrowIfNull(link);
        ArgumentNullException.ThrowIfNull(plan);
        ArgumentNullException.ThrowIfNull(settings);
        return new Bus(link, null, null, link.PortName, link, plan, settings, time ?? TimeProvider.System, logger ?? Serilog.Core.Logger.None, onChanges);
    }

    /// <summary>
    /// Starts polling <paramref name="plan"/> (Polling/PpiPollPlanner) over PPI on <paramref name="link"/>, which the
    /// bus owns from now on: no handler in the PLC, so no IDENTIFY and no STOP; <see cref="IdentifyPpiAsync"/> reads
    /// what PPI can tell instead.
    /// </summary>
    public static Bus StartPpi(PpiLink link, PollPlan plan, BusSettings settings, TimeProvider? time = null, ILogger? logger = null, Action<IReadOnlyList<ValueChange>>? onChanges = null)
    {
        ArgumentNullException.ThrowIfNull(link);
        ArgumentNullException.ThrowIfNull(plan);
        ArgumentNullException.ThrowIfNull(settings);
        return new Bus(new FreeportRefusedLink(link.PortName), link, null, link.PortName, link, plan, settings, time ?? TimeProvider.System, logger ?? Serilog.Core.Logger.None, onChanges);
    }

    /// <summary>
    /// Starts polling <paramref name="plan"/> in protocol v3 on <paramref name="link"/>, which the bus owns from now on:
    /// how every Freeport bus of a project runs (Line/ProjectLine). Writes, IDENTIFY, STOP and the settling of cut-short
    /// writes go through the link's IPlcLink face; stations are read by the v3 readers (docs/v3-panel-side.md).
    /// </summary>
    public static Bus StartV3(V3Link link, PollPlan plan, BusSettings settings, TimeProvider? time = null, ILogger? logger = null, Action<IReadOnlyList<ValueChange>>? onChanges = null)
    {
        ArgumentNullException.ThrowIfNull(link);
        ArgumentNullException.ThrowIfNull(plan);
        ArgumentNullException.ThrowIfNull(settings);
        return new Bus(link, null, link, link.PortName, link, plan, settings, time ?? TimeProvider.System, logger ?? Serilog.Core.Logger.None, onChanges);
    }

    /// <summary>
    /// A bus refreshing on demand with plain READs: what one verb of <c>opanel</c> (read, write, identify, stop) or the
    /// wizard's connection test needs (it refreshes once or twice, so registering read lists would only cost time).
    /// </summary>
    public static Bus OnDemand(PlcLink link, PollPlan plan, TimeProvider? time = null, ILogger? logger = null, IAuditTrail? audit = null) =>
        Start(link, plan, BusSettings.OnDemand with { Audit = audit }, time, logger);

    /// <summary>As above in protocol v3: READ per range (a DEFINE LIST would cost more than the one or two refreshes it serves).</summary>
    public static Bus OnDemand(V3Link link, PollPlan plan, TimeProvider? time = null, ILogger? logger = null, IAuditTrail? audit = null) =>
        StartV3(link, plan, BusSettings.OnDemand with { Audit = audit }, time, logger);

    public string PortName { get; }

    /// <summary>Whether the bus speaks PPI (no handler) rather than Freeport.</summary>
    public bool IsPpi => _ppi is not null;

    /// <summary>A PPI bus's jobs, empty polls and repeats; null on a Freeport bus.</summary>
    public PpiCounters? PpiCounters => _ppi?.Counters;

    /// <summary>What keeps the whole bus from polling ("another master on the bus ..."); null when nothing does.</summary>
    public string? Problem => _ppi?.Problem;

    public PollPlan Plan => Volatile.Read(ref _engine).Plan;

    /// <summary>Continuous or on demand; switches the loop at once, and a new plan keeps it.</summary>
    public RefreshMode Mode
    {
        get => Volatile.Read(ref _engine).Mode;
        set => Volatile.Read(ref _engine).Mode = value;
    }

    /// <summary>One full cycle: on demand the only way values change; in continuous mode the next regular cycle.</summary>
    public Task<PollResult> RefreshAsync(CancellationToken cancellationToken = default) =>
        Volatile.Read(ref _engine).RequestRefreshAsync(cancellationToken);

    /// <summary>The next cycle without asking for one (<see cref="PollingEngine.NextCycleAsync"/>): the minimum period holds.</summary>
    public Task<PollResult> NextCycleAsync(CancellationToken cancellationToken = default) =>
        Volatile.Read(ref _engine).NextCycleAsync(cancellationToken);

    /// <summary>A write through the queue, ahead of the next exchange; the outcome is the PLC's read-back, never the request.</summary>
    public Task<WriteOutcome> WriteAsync(WriteRequest request, CancellationToken cancellationToken = default) =>
        Volatile.Read(ref _engine).WriteAsync(request, cancellationToken);

    /// <summary>
    /// IDENTIFY through the queue. What the reply says (READ CHANGES copies, FEATURES bit 2) chooses the station's
    /// readers from the next exchange on, and stays known to a new plan. A link failure is the reply's value.
    /// </summary>
    public Task<LinkReply> IdentifyAsync(Station station, CancellationToken cancellationToken = default) =>
        ExchangeAsync(new IdentifyRequest(station), cancellationToken);

    /// <summary>
    /// STOP through the queue, as one job (<see cref="RemoteStop"/>: IDENTIFY, 07 once, IDENTIFY), so no poll comes
    /// between. A STOP that left the station silent shows it as stopped by the panel instead of offline.
    /// </summary>
    public Task<StopOutcome> StopAsync(Station station, CancellationToken cancellationToken = default) => StopAsync(station, null, cancellationToken);

    /// <summary>
    /// STOP, sent only when the station's IDENTIFY fits <paramref name="expectedCpu"/> (null: the CPU the plan has for
    /// the station, when it has one).
    /// </summary>
    public Task<StopOutcome> StopAsync(Station station, CpuProfile? expectedCpu, CancellationToken cancellationToken = default) => _ppi is not null
        ? Task.FromResult<StopOutcome>(new StopOutcome.NotSent(station, $"{PortName} is a PPI bus: the panel stops a CPU only through its own handler"))
        : _queue.Enqueue($"STOP of {station}", ct => StopNowAsync(station, expectedCpu, ct), () => new StopOutcome.NotSent(station, "disconnected before STOP was sent"), cancellationToken);

    /// <summary>
    /// Settles, through the queue, the writes and STOPs that earlier programs on this port left cut short in
    /// <paramref name="journal"/> (Writes/UnfinishedWrites: read back, never written again), ahead of any write queued
    /// after it. Nothing is settled when polling stops first: a later start does it.
    /// </summary>
    public Task<(IReadOnlyList<CutShortWrite> Resolved, string? Problem)> SettleCutShortAsync(WriteJournal journal, CancellationToken cancellationToken = default)
    {
        ArgumentNullException.ThrowIfNull(journal);
        return _queue.Enqueue(
            $"settling writes cut short on {PortName}",
            ct => _ppi is { } ppi
                ? UnfinishedWrites.ResolveOverPpiAsync(journal, ppi, PortName, _time, _logger, ct)
                : UnfinishedWrites.ResolveAsync(journal, _link, PortName, _time, _logger, ct),
            () => ((IReadOnlyList<CutShortWrite>)[], null),
            cancellationToken);
    }

    /// <summary>
    /// What the station said in its last answered IDENTIFY on this bus; null before one answered. On a v3 bus the link's
    /// (it also hears the IDENTIFY the list reader sends itself), with the whole v3 identity in
    /// <see cref="IdentifyResponse.V3Identity"/>.
    /// </summary>
    public IdentifyResponse? IdentityOf(Station station)
    {
        var stored = _identities.GetValueOrDefault(station);
        return _v3?.IdentityOf(station) is { } v3 && stored?.V3Identity != v3 ? V3Link.AsIdentifyResponse(station, v3) : stored;
    }

    /// <summary>What the station's last IDENTIFY brought: its reply (a refusal included) or the failure; null before any.</summary>
    public LinkReply? LastIdentifyOf(Station station) => _lastIdentify.GetValueOrDefault(station);

    /// <summary>The station's state on this bus; for a silent station resting between tries, when it is tried next.</summary>
    public StationStatus StatusOf(Station station) => Volatile.Read(ref _engine).GetStationStatus(station);

    public LinkStatistics StatisticsFor(Station station) => _ppi?.StatisticsFor(station) ?? _link.StatisticsFor(station);

    /// <summary>The latest value of a watched address; false when the plan does not watch it.</summary>
    public bool TryGetValue(Station station, PlcAddress address, out PolledValue value) =>
        Volatile.Read(ref _engine).TryGetValue(station, address, out value);

    /// <summary>
    /// Polls another plan (an edited watch list) on the same port: the loop stops after its exchange on the wire and
    /// starts again on the new plan; the link, its counters, the station states and what IDENTIFY said carry over.
    /// </summary>
    public async Task WatchAsync(PollPlan plan)
    {
        ArgumentNullException.ThrowIfNull(plan);
        var mode = Mode;
        await StopPollingAsync().ConfigureAwait(false);
        Volatile.Write(ref _engine, NewEngine(plan, mode));
        _stop = new CancellationTokenSource();
        StartLoop();
    }

    /// <summary>
    /// Stops the loop after its exchange on the wire; queued jobs that never started get their abandoned outcome. The
    /// port stays open until <see cref="DisposeAsync"/> (the line stops what runs beside its ports in between).
    /// </summary>
    public async Task StopPollingAsync()
    {
        if (!_polling)
        {
            return;
        }

        _polling = false;
        await _stop.CancelAsync().ConfigureAwait(false);
        await _loop.ConfigureAwait(false);
        _stop.Dispose();
    }

    public async ValueTask DisposeAsync()
    {
        await StopPollingAsync().ConfigureAwait(false);
        await _wire.DisposeAsync().ConfigureAwait(false);
    }

    /// <summary>
    /// What PPI tells about the station (SMB6, SM0.7, SMW22-SMW26: <see cref="PpiIdentity"/>), read through the queue;
    /// the station's state follows. On a Freeport bus the answer says to use IDENTIFY.
    /// </summary>
    public Task<PpiIdentifyOutcome> IdentifyPpiAsync(Station station, CancellationToken cancellationToken = default) => _ppi is not { } ppi
        ? Task.FromResult(new PpiIdentifyOutcome(null, $"{PortName} is a Freeport bus: use IDENTIFY"))
        : _queue.Enqueue($"PPI identify of {station}", async ct =>
        {
            try
            {
                var results = await ppi.ReadAsync(station, PpiIdentity.Items, ct).ConfigureAwait(false);
                var identity = PpiIdentity.From(station, results, out var error);
                _stations.RecordReply(station, error);
                return new PpiIdentifyOutcome(identity, error);
            }
            catch (Transport.PlcCommunicationException failure)
            {
                return new PpiIdentifyOutcome(null, _stations.RecordFailure(station, failure).Message);
            }
        }, () => new PpiIdentifyOutcome(null, "disconnected before the identify was sent"), cancellationToken);

    /// <summary>One request through the queue, for IDENTIFY and for tests that play another client of the bus.</summary>
    internal Task<LinkReply> ExchangeAsync(PlcRequest request, CancellationToken cancellationToken = default) =>
        _queue.Enqueue($"{request.Command} to {request.Station}", ct => ExchangeNowAsync(request, ct), abandoned: null, cancellationToken);

    private async Task<LinkReply> ExchangeNowAsync(PlcRequest request, CancellationToken cancellationToken)
    {
        var reply = await _link.ExchangeAsync(request, cancellationToken).ConfigureAwait(false);
        if (request is IdentifyRequest)
        {
            _lastIdentify[request.Station] = reply;
        }

        if (reply.Response is IdentifyResponse identity)
        {
            _identities[identity.Station] = identity;
            Volatile.Read(ref _engine).NoteIdentity(identity);
        }

        return reply;
    }

    private async Task<StopOutcome> StopNowAsync(Station station, CpuProfile? expectedCpu, CancellationToken cancellationToken)
    {
        var cpu = expectedCpu ?? Volatile.Read(ref _engine).Plan.Cpus.GetValueOrDefault(station);
        var outcome = await new RemoteStop(_link, _logger, _audit, _time).StopAsync(station, cpu, cancellationToken).ConfigureAwait(false);
        if (outcome.IsStopped)
        {
            Volatile.Read(ref _engine).NoteStoppedByPanel(station);
        }

        return outcome;
    }

    private PollingEngine NewEngine(PollPlan plan, RefreshMode mode)
    {
        var engine = new PollingEngine(_link, plan, _stations, _queue, _time, _logger, _settings.Polling, _onChanges, _ppi, _v3)
        {
            Mode = mode,
            MinimumPeriod = _settings.MinimumPeriod,
            Audit = _audit,
        };
        foreach (var identity in _identities.Values)
        {
            engine.NoteIdentity(identity);
        }

        return engine;
    }

    private void StartLoop()
    {
        var engine = Volatile.Read(ref _engine);
        var stop = _stop.Token;
        _polling = true;
        _loop = Task.Run(() => engine.RunAsync(stop), CancellationToken.None);
    }
}
