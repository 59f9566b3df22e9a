using System.Globalization;
using Microsoft.Data.Sqlite;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Alarms;
using OperatorPanel.Historian.Recording;
using OperatorPanel.Historian.Storage;

namespace OperatorPanel.Historian.Journal;

/// <summary>
/// The alarm journal of a project: every raise, clear and acknowledgement with its time, the alarm's text and class as
/// they were, and who acknowledged. Entries are appended through the writer (never blocking the caller); searches read
/// the database on their own connection, after the entries queued before them are stored.
/// </summary>
public sealed class AlarmJournal
{
    private readonly string _path;
    private readonly HistoryWriter _writer;

    internal AlarmJournal(string path, HistoryWriter writer) => (_path, _writer) = (path, writer);

    public void Append(AlarmEvent entry, string? user)
    {
        ArgumentNullException.ThrowIfNull(entry);
        _writer.Enqueue(new AlarmRow(entry, user));
    }

    /// <summary>The entries matching <paramref name="filter"/>, oldest first; none when nothing was recorded yet.</summary>
    public async Task<IReadOnlyList<JournalEntry>> SearchAsync(JournalFilter filter)
    {
        ArgumentNullException.ThrowIfNull(filter);
        await _writer.FlushAsync().ConfigureAwait(false);
        var where = new List<string>();
        var parameters = new List<(string, object)>();
        if (filter.From is { } from)
        {
            where.Add("t >= $from");
            parameters.Add(("$from", HistoryTime.ToMs(from)));
        }

        if (filter.To is { } to)
        {
            where.Add("t <= $to");
            parameters.Add(("$to", HistoryTime.ToMs(to)));
        }

        if (filter.Station is { } station)
        {
            where.Add("station = $station");
            parameters.Add(("$station", station.Address));
        }

        if (filter.Class is { } alarmClass)
        {
            where.Add("class = $class");
            parameters.Add(("$class", Words.Of(alarmClass)));
        }

        if (!string.IsNullOrWhiteSpace(filter.Text))
        {
            where.Add("(text LIKE $text ESCAPE '\\' OR station_name LIKE $text ESCAPE '\\')");
            parameters.Add(("$text", "%" + EscapeLike(filter.Text.Trim()) + "%"));
        }

        var condition = where.Count == 0 ? string.Empty : "WHERE " + string.Join(" AND ", where);
        var sql = string.Create(CultureInfo.InvariantCulture, $"SELECT * FROM (SELECT {Columns} FROM alarm_events {condition} ORDER BY id DESC LIMIT {Math.Max(1, filter.Limit)}) ORDER BY id");
        return Query(sql, parameters);
    }

    /// <summary>
    /// Each alarm's entries since its latest raise, oldest first: what AlarmTracker.Restore needs to take up where the
    /// last run left off (an alarm still unacknowledged at shutdown waits again).
    /// </summary>
    public async Task<IReadOnlyList<AlarmEvent>> SinceLastRaiseAsync()
    {
        await _writer.FlushAsync().ConfigureAwait(false);
        const string Sql = $"""
            SELECT {Columns} FROM alarm_events e
            JOIN (SELECT station AS s, flag AS f, max(id) AS first FROM alarm_events WHERE event = 'raised' GROUP BY station, flag) r
              ON e.station = r.s AND e.flag = r.f AND e.id >= r.first
            ORDER BY e.id
            """;
        return [.. Query(Sql, []).Select(e => e.Event)];
    }

    /// <summary>
    /// Imports a project's old alarm history file (<see cref="AlarmHistoryFile"/>, JSON Lines beside the project) once:
    /// its entries join the journal and the file is left where it is, marked imported in the database. Returns how many
    /// entries were imported (0 when none or done before) and the file's own message, if any.
    /// </summary>
    public async Task<(int Imported, string? Message)> ImportOnceAsync(string projectPath, TimeProvider time)
    {
        ArgumentException.ThrowIfNullOrWhiteSpace(projectPath);
        var file = AlarmHistoryFile.PathFor(projectPath);
        var key = "imported:" + Path.GetFullPath(file);
        if (!File.Exists(file) || await IsMarkedAsync(key).ConfigureAwait(false))
        {
            return (0, null);
        }

        var load = new AlarmHistoryFile(file, time).Load();
        foreach (var entry in load.Events)
        {
            _writer.Enqueue(new AlarmRow(entry, null));
        }

        _writer.Enqueue(new MetaRow(key, time.GetUtcNow().ToString("O", CultureInfo.InvariantCulture)));
        await _writer.FlushAsync().ConfigureAwait(false);
        return (load.Events.Length, load.Message);
    }

    private const string Columns = "id, t, station, station_name, flag, event, state, class, text, user";

    private async Task<bool> IsMarkedAsync(string key)
    {
        await _writer.FlushAsync().ConfigureAwait(false);
        if (!File.Exists(_path))
        {
            return false;
        }

        using var connection = HistoryDatabase.OpenForReading(_path);
        using var command = connection.CreateCommand();
        command.CommandText = "SELECT count(*) FROM meta WHERE key = $key";
        command.Parameters.AddWithValue("$key", key);
        return Convert.ToInt64(command.ExecuteScalar(), CultureInfo.InvariantCulture) > 0;
    }

    private List<JournalEntry> Query(string sql, List<(string Name, object Value)> parameters)
    {
        if (!File.Exists(_path))
        {
            return [];
        }

        try
        {
            using var connection = HistoryDatabase.OpenForReading(_path);
            using var command = connection.CreateCommand();
            command.CommandText = sql;
            parameters.ForEach(p => command.Parameters.AddWithValue(p.Name, p.Value));
            using var reader = command.ExecuteReader();
            var entries = new List<JournalEntry>();
            while (reader.Read())
            {
                entries.Add(Read(reader));
            }

            return entries;
        }
        catch (Exception ex) when (ex is SqliteException or IOException)
        {
            throw HistoryErrors.Translate(ex, _path);
        }
    }

    private static JournalEntry Read(SqliteDataReader r)
    {
        var station = Station.TryCreate(r.GetInt32(2), out var s, out _) ? s : throw new HistoryException(HistoryErrorKind.Corrupt, $"station {r.GetInt32(2)} in the alarm journal");
        var flag = PlcAddress.TryParse(r.GetString(4), out var f, out _) ? f : throw new HistoryException(HistoryErrorKind.Corrupt, $"flag '{r.GetString(4)}' in the alarm journal");
        var entry = new AlarmEvent(
            HistoryTime.FromMs(r.GetInt64(1)), r.GetString(3), station, flag,
            Words.Parse<AlarmTransition>(r.GetString(5)), Words.Parse<AlarmState>(r.GetString(6)), Words.Parse<AlarmClass>(r.GetString(7)), r.GetString(8));
        return new JournalEntry(r.GetInt64(0), entry, r.IsDBNull(9) ? null : r.GetString(9));
    }

    private static string EscapeLike(string text) =>
        text.Replace("\\", "\\\\", StringComparison.Ordinal).Replace("%", "\\%", StringComparison.Ordinal).Replace("_", "\\_", StringComparison.Ordinal);
}
