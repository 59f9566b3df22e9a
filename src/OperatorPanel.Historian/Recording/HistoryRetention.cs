using Microsoft.Data.Sqlite;
using OperatorPanel.Core.Projects;
using OperatorPanel.Historian.Storage;
using Serilog;

namespace OperatorPanel.Historian.Recording;

/// <summary>
/// Keeps a project's history within its <see cref="HistorySettings.RetentionDays"/> and <see cref="HistorySettings.MaxSizeMb"/>:
/// run by the writer between batches, every <see cref="Period"/>, each step its own short transaction (one tag's old rows,
/// one hour of the oldest rows) so no batch waits long behind it. Past the size limit the oldest rows go first, an hour
/// at a time, until the database is under 90 % of the limit; freed pages are reused by new rows, and handed back to the
/// disk (incremental vacuum) when the file itself is over the limit.
/// </summary>
internal sealed class HistoryRetention(HistorySettings settings, TimeProvider time)
{
    public static readonly TimeSpan Period = TimeSpan.FromMinutes(10);

    /// <summary>Size steps per run: an hour of rows each; the rest waits for the next run.</summary>
    private const int MaxSizeSteps = 24;

    private DateTimeOffset _next = time.GetUtcNow();

    public void RunDue(SqliteConnection connection, ILogger log)
    {
        var now = time.GetUtcNow();
        if (now < _next)
        {
            return;
        }

        _next = now + Period;
        var cutoff = HistoryTime.ToMs(now - TimeSpan.FromDays(settings.RetentionDays));
        var removed = DeleteBefore(connection, cutoff, withEvents: true);
        removed += KeepUnderSize(connection);
        if (removed > 0)
        {
            log.Information("History retention removed {Rows} rows (kept {Days} days, at most {Mb} MB)", removed, settings.RetentionDays, settings.MaxSizeMb);
        }
    }

    /// <summary>Bytes the rows take: pages in use, not the free ones waiting for reuse.</summary>
    public static long UsedBytes(SqliteConnection connection) =>
        (HistoryDatabase.Scalar(connection, "PRAGMA page_count") - HistoryDatabase.Scalar(connection, "PRAGMA freelist_count"))
        * HistoryDatabase.Scalar(connection, "PRAGMA page_size");

    private long KeepUnderSize(SqliteConnection connection)
    {
        var limit = settings.MaxSizeMb * 1024L * 1024L;
        long removed = 0;
        for (var step = 0; step < MaxSizeSteps && UsedBytes(connection) > limit * 9 / 10; step++)
        {
            if (Oldest(connection) is not { } oldest)
            {
                break;
            }

            removed += DeleteBefore(connection, oldest + (long)TimeSpan.FromHours(1).TotalMilliseconds, withEvents: false);
        }

        var pageSize = HistoryDatabase.Scalar(connection, "PRAGMA page_size");
        if (HistoryDatabase.Scalar(connection, "PRAGMA page_count") * pageSize > limit && HistoryDatabase.Scalar(connection, "PRAGMA freelist_count") > 0)
        {
            HistoryDatabase.Execute(connection, "PRAGMA incremental_vacuum(4096)");
        }

        return removed;
    }

    /// <summary>The oldest sample's time: each tag's first row is one index seek.</summary>
    private static long? Oldest(SqliteConnection connection)
    {
        using var command = connection.CreateCommand();
        command.CommandText = "SELECT min((SELECT t FROM samples WHERE tag = tags.id ORDER BY t LIMIT 1)) FROM tags";
        return command.ExecuteScalar() is long t ? t : null;
    }

    /// <summary>Rows before <paramref name="cutoff"/>: samples tag by tag (each a range of the primary key), then the small tables.</summary>
    private static long DeleteBefore(SqliteConnection connection, long cutoff, bool withEvents)
    {
        var tagIds = new List<long>();
        using (var select = connection.CreateCommand())
        {
            select.CommandText = "SELECT id FROM tags";
            using var reader = select.ExecuteReader();
            while (reader.Read())
            {
                tagIds.Add(reader.GetInt64(0));
            }
        }

        long removed = 0;
        foreach (var id in tagIds)
        {
            removed += Delete(connection, "DELETE FROM samples WHERE tag = $id AND t < $cutoff", cutoff, id);
        }

        removed += Delete(connection, "DELETE FROM station_states WHERE t < $cutoff", cutoff);
        removed += Delete(connection, "DELETE FROM sessions WHERE last < $cutoff", cutoff);
        if (withEvents)
        {
            removed += Delete(connection, "DELETE FROM alarm_events WHERE t < $cutoff", cutoff);
            removed += Delete(connection, "DELETE FROM audit WHERE t < $cutoff", cutoff);
        }

        return removed;
    }

    private static int Delete(SqliteConnection connection, string sql, long cutoff, long? id = null)
    {
        using var command = connection.CreateCommand();
        command.CommandText = sql;
        command.Parameters.AddWithValue("$cutoff", cutoff);
        if (id is { } tag)
        {
            command.Parameters.AddWithValue("$id", tag);
        }

        return command.ExecuteNonQuery();
    }
}
