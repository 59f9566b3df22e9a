using System.Collections.Concurrent;
using System.Threading.Channels;
using Microsoft.Data.Sqlite;
using OperatorPanel.Core.Projects;
using OperatorPanel.Historian.Storage;
using Serilog;

namespace OperatorPanel.Historian.Recording;

/// <summary>
/// The one writer of a history database: rows are queued without waiting (<see cref="Enqueue"/> only touches a
/// concurrent queue, so the line that records never waits for the disk), and a background loop stores them once a
/// second in one transaction. A locked database or a full disk is reported once (<see cref="Problem"/>, a log warning);
/// the rows wait, up to <see cref="MaxPending"/>, and are stored when the database takes writes again; past that limit
/// new rows are counted as lost. Retention runs in the same loop, in short slices between batches.
/// </summary>
internal sealed partial class HistoryWriter : IAsyncDisposable
{
    /// <summary>About 20 MB of queued rows: half a minute of 2000 tags changing every 100 ms, or hours of a normal line.</summary>
    public const int MaxPending = 200_000;

    public static readonly TimeSpan FlushPeriod = TimeSpan.FromSeconds(1);

    private readonly ConcurrentQueue<HistoryRow> _queue = new();
    private readonly Channel<bool> _wake = Channel.CreateBounded<bool>(new BoundedChannelOptions(1) { FullMode = BoundedChannelFullMode.DropWrite });
    private readonly CancellationTokenSource _stop = new();
    private readonly TimeProvider _time;
    private readonly ILogger _log;
    private readonly string _source;
    private readonly HistoryRetention _retention;
    private readonly Task _loop;
    private readonly WriterTuning _tuning;
    private readonly DateTimeOffset _created;
    private int _queued;
    private long _lost;
    private long _written;

    public HistoryWriter(string path, HistorySettings settings, TimeProvider time, ILogger log, string source, WriterTuning? tuning = null)
    {
        ArgumentException.ThrowIfNullOrWhiteSpace(path);
        ArgumentNullException.ThrowIfNull(settings);
        (Path, _time, _log, _source) = (path, time, log, source);
        _tuning = tuning ?? new WriterTuning();
        _retention = new HistoryRetention(settings, time);
        _created = time.GetUtcNow();
        _loop = Task.Run(RunAsync);
    }

    public string Path { get; }

    /// <summary>Why rows are not being stored now, in the operator's words; null while all is well.</summary>
    public string? Problem { get; private set; }

    /// <summary>Raised (on the writer's thread) when <see cref="Problem"/> changes.</summary>
    public event EventHandler? ProblemChanged;

    /// <summary>Rows dropped since start: the queue was full while the database took no writes.</summary>
    public long Lost => Interlocked.Read(ref _lost);

    /// <summary>Rows stored since start.</summary>
    public long Written => Interlocked.Read(ref _written);

    /// <summary>Queues a row; never blocks. False (and counted in <see cref="Lost"/>) when the queue is full.</summary>
    public bool Enqueue(HistoryRow row)
    {
        if (Interlocked.Increment(ref _queued) > MaxPending)
        {
            Interlocked.Decrement(ref _queued);
            Interlocked.Increment(ref _lost);
            return false;
        }

        _queue.Enqueue(row);
        return true;
    }

    /// <summary>Completes when every row queued before the call has been stored, or its write has failed (see <see cref="Problem"/>).</summary>
    public Task FlushAsync()
    {
        var marker = new FlushMarker(new TaskCompletionSource(TaskCreationOptions.RunContinuationsAsynchronously));
        _queue.Enqueue(marker);
        _wake.Writer.TryWrite(true);
        // A flush after the loop has ended has nothing left to wait for.
        return Task.WhenAny(marker.Done.Task, _loop);
    }

    public async ValueTask DisposeAsync()
    {
        if (_stop.IsCancellationRequested)
        {
            return;
        }

        await _stop.CancelAsync().ConfigureAwait(false);
        await _loop.ConfigureAwait(false);
        _stop.Dispose();
    }

    private async Task RunAsync()
    {
        SqliteConnection? connection = null;
        var batch = new Batch();
        while (true)
        {
            var stopping = _stop.IsCancellationRequested;
            Take(batch);
            connection = Store(connection, batch, stopping);
            if (connection is not null && !stopping)
            {
                RunRetention(connection);
            }

            batch.CompleteMarkers();
            if (stopping)
            {
                break;
            }

            await WaitAsync().ConfigureAwait(false);
        }

        connection?.Dispose();
        Take(batch);
        batch.DropAll(); // nothing more will be written; flushes still complete
    }

    /// <summary>Until the next flush period, a flush request, or the stop.</summary>
    private async Task WaitAsync()
    {
        using var wait = CancellationTokenSource.CreateLinkedTokenSource(_stop.Token);
        var delay = Task.Delay(FlushPeriod, _time, wait.Token);
        var woken = _wake.Reader.WaitToReadAsync(wait.Token).AsTask();
        await Task.WhenAny(delay, woken).ConfigureAwait(false);
        await wait.CancelAsync().ConfigureAwait(false);
        _wake.Reader.TryRead(out _);
    }

    /// <summary>Moves the queued rows into the batch (after any rows of a failed batch, so order is kept).</summary>
    private void Take(Batch batch)
    {
        while (_queue.TryDequeue(out var row))
        {
            if (row is FlushMarker marker)
            {
                batch.Markers.Add(marker);
                continue;
            }

            Interlocked.Decrement(ref _queued);
            batch.Rows.Add(row);
        }
    }

    private void RunRetention(SqliteConnection connection)
    {
        try
        {
            _retention.RunDue(connection, _log);
        }
        catch (Exception ex) when (HistoryErrors.IsEnvironmental(ex))
        {
            // The next batch's write meets the same cause and reports it; retention tries again at its next turn.
            _log.Debug(ex, "History retention skipped");
        }
    }

    private void Report(string? problem)
    {
        if (problem == Problem)
        {
            return;
        }

        if (problem is not null)
        {
            _log.Warning("History not recorded: {Problem}; the line goes on and rows wait (up to {Max})", problem, MaxPending);
        }
        else
        {
            _log.Information("History recording resumed into {Path}; {Lost} rows were lost meanwhile", Path, Lost);
        }

        Problem = problem;
        ProblemChanged?.Invoke(this, EventArgs.Empty);
    }

    /// <summary>The rows taken and not yet stored, and the flushes waiting for them.</summary>
    private sealed class Batch
    {
        public List<HistoryRow> Rows { get; } = [];

        public List<FlushMarker> Markers { get; } = [];

        public void CompleteMarkers()
        {
            Markers.ForEach(m => m.Done.TrySetResult());
            Markers.Clear();
        }

        public void DropAll()
        {
            Rows.Clear();
            CompleteMarkers();
        }
    }
}
