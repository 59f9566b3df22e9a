using System.Globalization;
using Microsoft.Data.Sqlite;

namespace OperatorPanel.Historian.Storage;

/// <summary>
/// Opens a history database. The writer's connection creates it when missing (WAL, so the panel's readers never wait for
/// the writer nor it for them; synchronous NORMAL, which in WAL mode loses at most the last batches at a power cut, never
/// the file; incremental auto-vacuum, so retention can hand freed pages back to the disk a few at a time). Readers open
/// read-only connections of their own. Connections are not pooled: a closed database is closed, and its file can be
/// moved or deleted at once.
/// </summary>
internal static class HistoryDatabase
{
    /// <summary>How long a statement waits for another writer (the CLI and the panel recording one project) before it counts as locked.</summary>
    public static readonly TimeSpan BusyWait = TimeSpan.FromSeconds(2);

    /// <summary>A reader waits longer: a search the operator started may take a moment, a batch must not.</summary>
    private static readonly TimeSpan ReadWait = TimeSpan.FromSeconds(10);

    /// <param name="path">The database file; its folder is made when missing.</param>
    /// <param name="busyWait">How long a statement waits for another writer; <see cref="BusyWait"/> unless a test says otherwise.</param>
    public static SqliteConnection OpenForWriting(string path, TimeSpan? busyWait = null)
    {
        var folder = Path.GetDirectoryName(Path.GetFullPath(path));
        if (folder is not null)
        {
            Directory.CreateDirectory(folder);
        }

        var connection = new SqliteConnection(ConnectionString(path, SqliteOpenMode.ReadWriteCreate, busyWait ?? BusyWait));
        try
        {
            connection.Open();
            Execute(connection, "PRAGMA auto_vacuum = INCREMENTAL; PRAGMA journal_mode = WAL; PRAGMA synchronous = NORMAL;");
            EnsureSchema(connection, path);
            return connection;
        }
        catch
        {
            connection.Dispose();
            throw;
        }
    }

    /// <summary>A read-only connection; the database must exist (<see cref="SqliteException"/> otherwise).</summary>
    public static SqliteConnection OpenForReading(string path)
    {
        var connection = new SqliteConnection(ConnectionString(path, SqliteOpenMode.ReadOnly, ReadWait));
        try
        {
            connection.Open();
            var version = UserVersion(connection);
            if (version == 0)
            {
                throw new HistoryException(HistoryErrorKind.NotAHistory, $"{path} is not an Operator Panel history database");
            }

            return connection;
        }
        catch
        {
            connection.Dispose();
            throw;
        }
    }

    public static void Execute(SqliteConnection connection, string sql)
    {
        using var command = connection.CreateCommand();
        command.CommandText = sql;
        command.ExecuteNonQuery();
    }

    public static long Scalar(SqliteConnection connection, string sql)
    {
        using var command = connection.CreateCommand();
        command.CommandText = sql;
        return Convert.ToInt64(command.ExecuteScalar() ?? 0L, CultureInfo.InvariantCulture);
    }

    private static string ConnectionString(string path, SqliteOpenMode mode, TimeSpan busyWait) => new SqliteConnectionStringBuilder
    {
        DataSource = path,
        Mode = mode,
        Pooling = false,
        // Whole seconds, and never 0, which Microsoft.Data.Sqlite takes as "wait for ever".
        DefaultTimeout = Math.Max(1, (int)busyWait.TotalSeconds),
    }.ToString();

    private static int UserVersion(SqliteConnection connection) => (int)Scalar(connection, "PRAGMA user_version");

    private static void EnsureSchema(SqliteConnection connection, string path)
    {
        var version = UserVersion(connection);
        if (version > HistorySchema.Version)
        {
            throw new HistoryException(
                HistoryErrorKind.NewerSchema,
                $"{path} was written by a newer Operator Panel (history schema {version}, this program writes {HistorySchema.Version}); nothing is recorded into it");
        }

        if (version == HistorySchema.Version)
        {
            return;
        }

        if (Scalar(connection, "SELECT count(*) FROM sqlite_master") > 0)
        {
            throw new HistoryException(HistoryErrorKind.NotAHistory, $"{path} holds tables of something else: not an Operator Panel history database");
        }

        using var transaction = connection.BeginTransaction();
        Execute(connection, HistorySchema.CreateV1);
        Execute(connection, $"PRAGMA user_version = {HistorySchema.Version}");
        transaction.Commit();
    }
}
