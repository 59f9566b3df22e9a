using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Audit;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Polling.Readers;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Writes;
using Serilog;
using Serilog.Core;

namespace OperatorPanel.Core.Polling;

/// <summary>
/// The polling loop of one bus: keeps the watched values of a <see cref="PollPlan"/> up to date over an
/// <see cref="IPlcLink"/> and carries the operator's writes, in the two modes of seed 000 §7. One loop
/// (<see cref="RunAsync"/>, PollingEngine.Loop.cs) does all link traffic, so one request is on the wire at a time: a cycle
/// asks each station's readers (Readers/ReaderChoice, chosen from its IDENTIFY) for its frames, and queued writes go
/// ahead of the next exchange (Writes/IStationWriter). Failures never escape the loop: they become value qualities,
/// <see cref="StationStatus"/>es and log entries, and polling goes on. All waiting uses the injected
/// <see cref="TimeProvider"/>. Two files: this one holds the state, what callers use and the write job; the loop is the
/// other. Outside Core a bus is reached through Line/Bus, which owns its engine.
/// </summary>
internal sealed partial class PollingEngine
{
    private readonly PollingContext _context;
    private readonly ValueStore _values;
    private readonly ReaderChoice _readers;
    private readonly OfflineRest _rest;
    private readonly BusQueue _queue;
    private readonly CycleSchedule _schedule;
    private readonly Action<IReadOnlyList<ValueChange>> _onChanges;

    /// <summary>The changes of the cycle or job under way, handed on whole at its end; the loop's thread only.</summary>
    private readonly List<ValueChange> _batch = [];

    /// <param name="link">The bus's link.</param>
    /// <param name="plan">What to read.</param>
    /// <param name="timeProvider">The clock of every wait.</param>
    /// <param name="logger">Where failures and writes are logged.</param>
    /// <param name="options">How lists are read and silent stations rested.</param>
    /// <param name="onChanges">
    /// Hears, on the loop's thread, the batch of changed values (value or quality) after every cycle and every job of the
    /// queue (a write's read-back), an empty batch included: the bus's owner (Line/ProjectLine) routes the changes and
    /// refreshes what shows station states and link counters. A throwing listener is logged; polling goes on.
    /// </param>
    public PollingEngine(
        IPlcLink link, PollPlan plan, TimeProvider? timeProvider = null, ILogger? logger = null, PollingOptions? options = null, Action<IReadOnlyList<ValueChange>>? onChanges = null)
        : this(link, plan, null, null, timeProvider ?? TimeProvider.System, logger ?? Logger.None, options ?? new PollingOptions(), onChanges)
    {
    }

    /// <summary>
    /// An engine for a bus that keeps its station states and its queue across plans (Line/Bus); with
    /// <paramref name="ppi"/> the bus speaks PPI and its stations are read and written over it.
    /// </summary>
    public PollingEngine(
        IPlcLink link, PollPlan plan, StationTracker? stations, BusQueue? queue, TimeProvider time, ILogger logger, PollingOptions options, Action<IReadOnlyList<ValueChange>>? onChanges, PpiLink? ppi = null, Link.V3.V3Link? v3 = null)
    {
        ArgumentNullException.ThrowIfNull(link);
        ArgumentNullException.ThrowIfNull(plan);
        var log = logger.ForContext<PollingEngine>();
        stations ??= new StationTracker(time, log);
        _context = new PollingContext(plan, link, new FrameJudge(stations), options, time, log) { Ppi = ppi, V3 = v3 };
        _values = new ValueStore(plan.Values.Select(v => v.Item), time.GetUtcNow());
        _readers = new ReaderChoice(_context);
        _rest = new OfflineRest(stations, log);
        _queue = queue ?? new BusQueue(log);
        _schedule = new CycleSchedule(_queue.Wake, time);
        _onChanges = onChanges ?? (_ => { });
    }

    public PollPlan Plan => _context.Plan;

    private PollingOptions Options => _context.Options;

    /// <summary>Switchable while running; the loop notices at once.</summary>
    public RefreshMode Mode
    {
        get => _schedule.Mode;
        set => _schedule.Mode = value;
    }

    /// <summary>In continuous mode a cycle never starts sooner than this after the previous cycle started. Default 100 ms.</summary>
    public TimeSpan MinimumPeriod
    {
        get => _schedule.MinimumPeriod;
        set => _schedule.MinimumPeriod = value;
    }

    /// <summary>
    /// Where writes go on record (the write journal, with the bus's port and the user): each write's intent before it is
    /// handed to the writer that sends it (a write whose intent cannot be recorded is not sent), its outcome before the
    /// caller hears it. Null records nothing. STOPs go on record in Stop/RemoteStop.
    /// </summary>
    public AuditContext? Audit { get; init; }

    private StationTracker Stations => _context.Judge.Stations;

    /// <summary>The latest value of a watched address; false when the plan does not watch it.</summary>
    public bool TryGetValue(Station station, PlcAddress address, out PolledValue value) =>
        _values.TryGet(new WatchedItem(station, address), out value);

    /// <summary>The station's link state; for a silent station resting between tries, when it is tried next.</summary>
    public StationStatus GetStationStatus(Station station)
    {
        var status = Stations.Get(station);
        return _rest.NextTry(status, Mode, Options.OfflineRetryInterval) is { } next ? status with { NextTryAt = next } : status;
    }

    /// <summary>The panel stopped the station (Stop/RemoteStop confirmed it): its silence is no longer news.</summary>
    public void NoteStoppedByPanel(Station station) => Stations.RecordStoppedByPanel(station);

    /// <summary>What an IDENTIFY reply says about the station's handler chooses its readers from the next exchange on.</summary>
    public void NoteIdentity(IdentifyResponse identity) => _readers.NoteIdentity(identity);

    /// <summary>
    /// Asks for one full cycle now and returns its result ("Refresh now"): in <see cref="RefreshMode.OnDemand"/> this is
    /// what makes the engine poll; in continuous mode the cycle runs at once, without waiting out the minimum period.
    /// Cancelled when polling stops first.
    /// </summary>
    public Task<PollResult> RequestRefreshAsync(CancellationToken cancellationToken = default) => _schedule.RequestRefresh(cancellationToken);

    /// <summary>
    /// The result of the next cycle without asking for one: in continuous mode the next regular cycle (the minimum
    /// period holds, as for a live view following the polling), in triggered mode a refresh request.
    /// </summary>
    public Task<PollResult> NextCycleAsync(CancellationToken cancellationToken = default) => _schedule.NextCycle(cancellationToken);

    /// <summary>
    /// Queues a write on the bus's queue and returns its outcome once sent and read back; it goes ahead of the next
    /// exchange, never inside one. The write waits while <see cref="RunAsync"/> is not running. Cancelling
    /// <paramref name="cancellationToken"/> withdraws it only while it is still queued. Every write is logged with old and
    /// new value and its outcome (Writes/WriteLog).
    /// </summary>
    public Task<WriteOutcome> WriteAsync(WriteRequest request, CancellationToken cancellationToken = default)
    {
        ArgumentNullException.ThrowIfNull(request);
        return _queue.Enqueue($"Write {request}", ct => WriteNowAsync(request, ct), () => Record(request, OldValue(request), new WriteOutcome.Failed(
            "polling stopped before the write was sent; nothing was written", WriteFailureKind.EngineStopped)), cancellationToken);
    }

    /// <summary>
    /// The write job, on the loop between two exchanges: its intent goes on record, the bus's writer sends it, the
    /// read-back becomes values, its outcome goes on record and into the log before the caller hears it.
    /// </summary>
    private async Task<WriteOutcome> WriteNowAsync(WriteRequest request, CancellationToken cancellationToken)
    {
        var oldRaw = OldValue(request);
        var (intent, notRecorded) = await WriteAudit.RecordIntentAsync(Audit, request, WriteLog.Format(request.Address, oldRaw), _context.Time.GetUtcNow()).ConfigureAwait(false);
        if (notRecorded is not null)
        {
            return Record(request, oldRaw, notRecorded);
        }

        var (outcome, oldText) = await SendAsync(request, oldRaw, cancellationToken).ConfigureAwait(false);
        await WriteAudit.RecordOutcomeAsync(Audit, intent, request, outcome, _context.Time.GetUtcNow(), _context.Logger).ConfigureAwait(false);
        WriteLog.Record(_context.Logger, request, oldText, outcome);
        return outcome;
    }

    /// <summary>Hands the write to the bus's writer; any end is an outcome, with the old value as the log shows it.</summary>
    private async Task<(WriteOutcome Outcome, string OldText)> SendAsync(WriteRequest request, ImmutableArray<byte> oldRaw, CancellationToken cancellationToken)
    {
        var oldText = WriteLog.Format(request.Address, oldRaw);
        try
        {
            var result = await _readers.Writer.WriteAsync(request, oldRaw, cancellationToken).ConfigureAwait(false);
            if (!result.ReadBack.IsDefault)
            {
                _batch.AddRange(_values.Apply(request.Station, request.Address.Area, request.Address.ByteOffset, result.ReadBack, _context.Time.GetUtcNow()));
            }

            return (result.Outcome, oldText);
        }
        catch (OperationCanceledException) when (cancellationToken.IsCancellationRequested)
        {
            return (new WriteOutcome.Unknown(default, "polling stopped while the write was on the wire", "no read-back: the panel stopped polling"), oldText);
        }
        catch (Exception exception)
        {
            // A bug of ours must not leave the caller waiting forever: the write still gets an outcome.
            _context.Logger.Error(exception, "Write {Request} broke the engine's own handling", request.ToString());
            return (new WriteOutcome.Unknown(
                default, $"internal error: {exception.Message}", "the panel's own handling broke after the write may have been sent"), WriteLog.Unknown);
        }
    }

    private ImmutableArray<byte> OldValue(WriteRequest request) =>
        _values.TryGet(new WatchedItem(request.Station, request.Address), out var old) && old.HasValue ? old.Raw : default;

    private WriteOutcome Record(WriteRequest request, ImmutableArray<byte> oldRaw, WriteOutcome outcome)
    {
        WriteLog.Record(_context.Logger, request, WriteLog.Format(request.Address, oldRaw), outcome);
        return outcome;
    }

    /// <summary>The end of a cycle or a job: its changes, maybe none, go to the listener in one batch.</summary>
    private void Flush()
    {
        var batch = _batch.ToArray();
        _batch.Clear();
        try
        {
            _onChanges(batch);
        }
        catch (Exception exception)
        {
            _context.Logger.Error(exception, "A value subscriber threw; polling continues");
        }
    }
}
