using Microsoft.Data.Sqlite;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Audit;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Projects;
using OperatorPanel.Historian.Recording;
using OperatorPanel.Historian.Storage;

namespace OperatorPanel.Historian.Reading;

/// <summary>
/// Reads a history database on connections of its own (read-only; WAL lets them run beside the writer). A database that
/// does not exist yet reads as empty; one that cannot be read throws <see cref="HistoryException"/>.
/// </summary>
public sealed class HistoryReader(string path)
{
    public string Path { get; } = path;

    public bool Exists => File.Exists(Path);

    /// <summary>The history of each of <paramref name="tags"/>, its numbers and texts in the tag's engineering units (scale and unit as the project has them now).</summary>
    public IReadOnlyList<TagHistory> Read(IReadOnlyList<RecordedTag> tags, DateTimeOffset from, DateTimeOffset to)
    {
        ArgumentNullException.ThrowIfNull(tags);
        return [.. Read(tags.Select(t => (t.Station, t.Address)), from, to).Zip(tags, (history, tag) => history with { Scale = tag.Scale, Unit = tag.Unit })];
    }

    /// <summary>
    /// The rows of each of <paramref name="values"/> from <paramref name="from"/> to <paramref name="to"/>, with the last
    /// row before <paramref name="from"/> (the value the range starts with); a value never recorded has no rows.
    /// </summary>
    public IReadOnlyList<TagHistory> Read(IEnumerable<(Station Station, PlcAddress Address)> values, DateTimeOffset from, DateTimeOffset to)
    {
        ArgumentNullException.ThrowIfNull(values);
        return Run(connection => values.Select(v => ReadOne(connection, v.Station, v.Address, HistoryTime.ToMs(from), HistoryTime.ToMs(to))).ToList(), []);
    }

    /// <summary>When the recorder ran, overlapping the range, oldest first.</summary>
    public IReadOnlyList<RecordingSpan> Sessions(DateTimeOffset from, DateTimeOffset to) => Run(
        connection =>
        {
            using var command = Command(connection, "SELECT started, last, source FROM sessions WHERE last >= $from AND started <= $to ORDER BY started", from, to);
            using var reader = command.ExecuteReader();
            var spans = new List<RecordingSpan>();
            while (reader.Read())
            {
                spans.Add(new RecordingSpan(HistoryTime.FromMs(reader.GetInt64(0)), HistoryTime.FromMs(reader.GetInt64(1)), reader.GetString(2)));
            }

            return spans;
        },
        []);

    /// <summary>The audit of writes and STOPs in the range, oldest first: each action's intent, then its outcome.</summary>
    public IReadOnlyList<AuditEntry> Audit(DateTimeOffset from, DateTimeOffset to) => Run(
        connection =>
        {
            using var command = Command(
                connection,
                "SELECT t, action_id, step, action, user, port, station, target, symbol, old_value, new_value, outcome, detail FROM audit WHERE t >= $from AND t <= $to ORDER BY id",
                from,
                to);
            using var reader = command.ExecuteReader();
            var entries = new List<AuditEntry>();
            while (reader.Read())
            {
                var station = Station.TryCreate(reader.GetInt32(6), out var s, out _) ? s : throw new HistoryException(HistoryErrorKind.Corrupt, "a station in the audit");
                string? Text(int column) => reader.IsDBNull(column) ? null : reader.GetString(column);
                entries.Add(new AuditEntry(
                    Guid.Parse(reader.GetString(1)), Words.Parse<AuditStep>(reader.GetString(2)), Words.Parse<AuditAction>(reader.GetString(3)),
                    HistoryTime.FromMs(reader.GetInt64(0)), reader.GetString(4), reader.GetString(5), station, Text(7), Text(8), reader.GetString(9),
                    reader.GetString(10), Text(11), Text(12)));
            }

            return entries;
        },
        []);

    /// <summary>What the database holds: rows per table and the bytes in use.</summary>
    public HistoryFigures Figures() => Run(
        connection => new HistoryFigures(
            HistoryDatabase.Scalar(connection, "SELECT count(*) FROM samples"),
            HistoryDatabase.Scalar(connection, "SELECT count(*) FROM tags"),
            HistoryDatabase.Scalar(connection, "SELECT count(*) FROM alarm_events"),
            HistoryDatabase.Scalar(connection, "SELECT count(*) FROM audit"),
            new FileInfo(Path).Length + (File.Exists(Path + "-wal") ? new FileInfo(Path + "-wal").Length : 0)),
        new HistoryFigures(0, 0, 0, 0, 0));

    private T Run<T>(Func<SqliteConnection, T> read, T empty)
    {
        if (!Exists)
        {
            return empty;
        }

        try
        {
            using var connection = HistoryDatabase.OpenForReading(Path);
            return read(connection);
        }
        catch (Exception ex) when (ex is SqliteException or IOException)
        {
            throw HistoryErrors.Translate(ex, Path);
        }
    }

    private static TagHistory ReadOne(SqliteConnection connection, Station station, PlcAddress address, long from, long to)
    {
        using var tag = connection.CreateCommand();
        tag.CommandText = "SELECT id, symbol, format FROM tags WHERE station = $station AND address = $address";
        tag.Parameters.AddWithValue("$station", station.Address);
        tag.Parameters.AddWithValue("$address", address.ToString());
        using var found = tag.ExecuteReader();
        if (!found.Read())
        {
            return new TagHistory(station, address, address.ToString(), DisplayFormat.Unsigned, []);
        }

        var (id, symbol, format) = (found.GetInt64(0), found.GetString(1), Words.Parse<DisplayFormat>(found.GetString(2)));
        using var rows = connection.CreateCommand();
        rows.CommandText = """
            SELECT t, value, quality FROM (SELECT t, value, quality FROM samples WHERE tag = $id AND t < $from ORDER BY t DESC LIMIT 1)
            UNION ALL
            SELECT t, value, quality FROM samples WHERE tag = $id AND t >= $from AND t <= $to
            ORDER BY t
            """;
        rows.Parameters.AddWithValue("$id", id);
        rows.Parameters.AddWithValue("$from", from);
        rows.Parameters.AddWithValue("$to", to);
        using var reader = rows.ExecuteReader();
        var samples = new List<HistorySample>();
        while (reader.Read())
        {
            samples.Add(new HistorySample(HistoryTime.FromMs(reader.GetInt64(0)), reader.IsDBNull(1) ? null : reader.GetInt64(1), (ValueQuality)reader.GetInt32(2)));
        }

        return new TagHistory(station, address, symbol, format, samples);
    }

    private static SqliteCommand Command(SqliteConnection connection, string sql, DateTimeOffset from, DateTimeOffset to)
    {
        var command = connection.CreateCommand();
        command.CommandText = sql;
        command.Parameters.AddWithValue("$from", HistoryTime.ToMs(from));
        command.Parameters.AddWithValue("$to", HistoryTime.ToMs(to));
        return command;
    }
}
