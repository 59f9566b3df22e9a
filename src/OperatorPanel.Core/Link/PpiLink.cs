using System.Collections.Concurrent;
using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Ppi;
using OperatorPanel.Core.Ppi.S7;
using OperatorPanel.Core.Transport;
using Serilog;

namespace OperatorPanel.Core.Link;

/// <summary>
/// The link of a PPI bus (docs/ppi.md sections 4 and 14): its port, opened before each job, and the one
/// <see cref="PpiMaster"/> on it, so every job on the port, read or write, takes the next PDU reference of one sequence
/// (section 5.1: a late answer to the previous job is never taken for the pending one). Reads repeat an unacknowledged
/// job; a write job goes out once, as the Freeport link never repeats a request that acts on the process (a write whose
/// answer is lost is settled by a read-back, never sent again); polls without a sound answer are repeated for both,
/// with the same frame count bit, which fetches the answer again without doing the job again. After another master
/// was seen the link stays off the bus for <see cref="AnotherMasterRest"/> (every job fails at once, nothing is sent) and
/// <see cref="Problem"/> says so. One job at a time: its bus (Line/Bus) is its one caller, through the bus's queue.
/// </summary>
public sealed class PpiLink : IAsyncDisposable
{
    private readonly ITransport _transport;
    private readonly TimeProvider _time;
    private readonly PpiMaster _master;
    private readonly ConcurrentDictionary<Station, StationStatistics> _statistics = new();
    private DateTimeOffset? _anotherMasterAt;
    private string? _problem;

    /// <summary>A link at <paramref name="baudRate"/> with the master's default time-outs (docs/ppi.md section 9).</summary>
    public PpiLink(ITransport transport, int baudRate, TimeProvider? time = null, ILogger? log = null)
        : this(transport, PpiMasterOptions.ForBaud(baudRate), time, log)
    {
    }

    public PpiLink(ITransport transport, PpiMasterOptions options, TimeProvider? time = null, ILogger? log = null)
    {
        ArgumentNullException.ThrowIfNull(transport);
        ArgumentNullException.ThrowIfNull(options);
        _transport = transport;
        _time = time ?? TimeProvider.System;
        _master = new PpiMaster(transport, options, _time, log);
    }

    /// <summary>How long the link keeps off the bus after it saw another master. Not from a source: long enough not to disturb a programming session.</summary>
    public TimeSpan AnotherMasterRest { get; init; } = TimeSpan.FromSeconds(10);

    public string PortName => _transport.Name;

    /// <summary>"another master on the bus ..." while the link keeps off the bus; null otherwise.</summary>
    public string? Problem => Volatile.Read(ref _problem);

    /// <summary>Jobs answered, polls answered "no data yet", frames sent again.</summary>
    public PpiCounters Counters => new(_master.Exchanges, _master.EmptyPolls, _master.Repeats);

    /// <summary>Per station, as on a Freeport link: a job is a request; its repeats are retries; a silent job a time-out.</summary>
    public LinkStatistics StatisticsFor(Station station) =>
        _statistics.TryGetValue(station, out var statistics) ? statistics.Snapshot() : LinkStatistics.Empty;

    /// <summary>
    /// Opens the port when it is closed and refuses while the link keeps off the bus: a failure here means nothing was
    /// sent (a <see cref="PlcCommunicationException"/>, kind PortUnavailable or AnotherMaster).
    /// </summary>
    public async Task EnsureReadyAsync(Station station, CancellationToken cancellationToken)
    {
        if (_anotherMasterAt is { } seen && _time.GetUtcNow() - seen < AnotherMasterRest)
        {
            throw new PlcCommunicationException(PlcErrorKind.AnotherMaster, station,
                $"another master on the bus: the panel keeps off it until {(seen + AnotherMasterRest).ToLocalTime():HH:mm:ss} ({Problem})");
        }

        if (!_transport.IsOpen)
        {
            await _transport.OpenAsync(cancellationToken).ConfigureAwait(false);
        }
    }

    public Task<ImmutableArray<S7ItemResult>> ReadAsync(Station station, IReadOnlyList<S7Item> items, CancellationToken cancellationToken) =>
        RunAsync(station, master => master.ReadAsync(station, items, cancellationToken), cancellationToken);

    /// <summary>A write job sent once (its polls repeated); a failure after <see cref="EnsureReadyAsync"/> may have reached the CPU.</summary>
    public Task<ImmutableArray<S7ReturnCode>> WriteAsync(Station station, IReadOnlyList<S7WriteItem> items, CancellationToken cancellationToken) =>
        RunAsync(station, master => master.WriteAsync(station, items, cancellationToken), cancellationToken);

    public async ValueTask DisposeAsync() => await _transport.DisposeAsync().ConfigureAwait(false);

    private async Task<T> RunAsync<T>(Station station, Func<PpiMaster, Task<T>> job, CancellationToken cancellationToken)
    {
        var master = _master;
        await EnsureReadyAsync(station, cancellationToken).ConfigureAwait(false);
        var statistics = _statistics.GetOrAdd(station, _ => new StationStatistics());
        var (started, repeats) = (_time.GetTimestamp(), master.Repeats);
        try
        {
            var result = await job(master).ConfigureAwait(false);
            (_anotherMasterAt, _problem) = (null, null);
            statistics.Reply(_time.GetElapsedTime(started));
            return result;
        }
        catch (PlcCommunicationException failure)
        {
            Action count = failure.Kind switch
            {
                PlcErrorKind.FrameCorrupt => statistics.Corrupt,
                PlcErrorKind.NegativeReply => statistics.NegativeReply,
                _ => statistics.Timeout,
            };
            count();
            if (failure.Kind == PlcErrorKind.AnotherMaster)
            {
                NoteAnotherMaster();
            }

            throw;
        }
        finally
        {
            statistics.Request();
            for (var i = repeats; i < master.Repeats; i++)
            {
                statistics.Retry();
            }
        }
    }

    private void NoteAnotherMaster()
    {
        _anotherMasterAt = _time.GetUtcNow();
        Volatile.Write(ref _problem, $"another master on the bus since {_anotherMasterAt.Value.ToLocalTime():HH:mm:ss}: the panel reads only while it is the bus's one master");
    }
}
