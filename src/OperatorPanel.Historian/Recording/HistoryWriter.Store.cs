using Microsoft.Data.Sqlite;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Historian.Storage;

namespace OperatorPanel.Historian.Recording;

/// <summary>Storing one batch: open the database when needed, one transaction for every row, failures kept to one form.</summary>
internal sealed partial class HistoryWriter
{
    private readonly Dictionary<(Station, PlcAddress), long> _tagIds = [];
    /// <summary>An idle writer still moves its session's end on this often, so a flat, quiet line reads as recorded.</summary>
    private static readonly TimeSpan IdleMark = TimeSpan.FromMinutes(1);

    private long? _session;
    private DateTimeOffset _lastMark;

    /// <summary>
    /// Stores the batch's rows and moves the session's end to now; returns the connection to keep (null after a failure,
    /// so the next try reopens). A batch without rows is skipped while the last mark is recent, unless a flush asked for
    /// it: a flush leaves the session's end at the flush's time, whenever the loop last woke before it.
    /// </summary>
    private SqliteConnection? Store(SqliteConnection? connection, Batch batch, bool stopping)
    {
        if (batch.Rows.Count == 0 && batch.Markers.Count == 0 && !stopping && _session is not null && _time.GetUtcNow() - _lastMark < IdleMark)
        {
            return connection;
        }

        try
        {
            connection ??= Open();
            _lastMark = _time.GetUtcNow();
            var now = HistoryTime.ToMs(_lastMark);
            using (var transaction = connection.BeginTransaction())
            {
                using var rows = new RowWriter(connection, transaction, _tagIds);
                batch.Rows.ForEach(rows.Write);
                MarkSession(connection, transaction, now, Earliest(batch), stopping);
                transaction.Commit();
            }

            Interlocked.Add(ref _written, batch.Rows.Count);
            batch.Rows.Clear();
            Report(null);
            return connection;
        }
        catch (Exception ex) when (HistoryErrors.IsEnvironmental(ex))
        {
            connection?.Dispose();
            // Ids handed out inside the failed transaction are gone with it.
            _tagIds.Clear();
            _session = null;
            Fail(HistoryErrors.Translate(ex, Path), batch);
            return null;
        }
    }

    /// <summary>
    /// The session started when the writer was made, or with an earlier row (a value read before recording began, handed
    /// over with its read time), so the first rows are inside their own session.
    /// </summary>
    private long Earliest(Batch batch)
    {
        var earliest = _created;
        foreach (var row in batch.Rows)
        {
            if (row is SampleRow sample && sample.At < earliest)
            {
                earliest = sample.At;
            }
        }

        return HistoryTime.ToMs(earliest);
    }

    private SqliteConnection Open()
    {
        var connection = HistoryDatabase.OpenForWriting(Path, _tuning.BusyWait);
        _tuning.OnOpened?.Invoke(connection);
        return connection;
    }

    private void Fail(HistoryException failure, Batch batch)
    {
        var permanent = failure.Kind is HistoryErrorKind.NewerSchema or HistoryErrorKind.NotAHistory or HistoryErrorKind.Corrupt;
        var drop = permanent ? batch.Rows.Count : Math.Max(0, batch.Rows.Count - MaxPending);
        if (drop > 0)
        {
            batch.Rows.RemoveRange(0, drop);
            Interlocked.Add(ref _lost, drop);
        }

        Report(failure.Message);
    }

    /// <summary>
    /// The recording session: its row is made with the first transaction and its "last" moved on with every one, so a
    /// reader knows the recorder ran until then (a value holds between its rows only while it did); "ended" at a clean stop.
    /// </summary>
    private void MarkSession(SqliteConnection connection, SqliteTransaction transaction, long now, long started, bool stopping)
    {
        using var command = connection.CreateCommand();
        command.Transaction = transaction;
        command.Parameters.AddWithValue("$now", now);
        if (_session is not { } id)
        {
            command.CommandText = "INSERT INTO sessions (started, last, ended, source) VALUES ($started, $now, NULL, $source) RETURNING id";
            command.Parameters.AddWithValue("$started", Math.Min(started, now));
            command.Parameters.AddWithValue("$source", _source);
            _session = Convert.ToInt64(command.ExecuteScalar(), System.Globalization.CultureInfo.InvariantCulture);
            id = _session.Value;
            command.Parameters.Clear();
            command.Parameters.AddWithValue("$now", now);
        }

        command.CommandText = stopping ? "UPDATE sessions SET last = $now, ended = $now WHERE id = $id" : "UPDATE sessions SET last = $now WHERE id = $id";
        command.Parameters.AddWithValue("$id", id);
        command.ExecuteNonQuery();
    }
}
