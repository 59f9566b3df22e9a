using Microsoft.Data.Sqlite;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Historian.Storage;

namespace OperatorPanel.Historian.Recording;

/// <summary>
/// The INSERTs of one transaction, each a prepared command reused row after row (parameters rebound, not re-parsed):
/// what keeps thousands of rows a second cheap.
/// </summary>
internal sealed class RowWriter(SqliteConnection connection, SqliteTransaction transaction, Dictionary<(Station, PlcAddress), long> tagIds) : IDisposable
{
    private SqliteCommand? _sample;
    private SqliteCommand? _tag;

    public void Dispose()
    {
        _sample?.Dispose();
        _tag?.Dispose();
    }

    public void Write(HistoryRow row)
    {
        switch (row)
        {
            case SampleRow sample:
                WriteSample(sample);
                break;
            case StationStateRow state:
                Insert(
                    "INSERT OR REPLACE INTO station_states (station, t, state, error) VALUES ($station, $t, $state, $error)",
                    ("$station", state.Station.Address), ("$t", HistoryTime.ToMs(state.At)), ("$state", Words.Of(state.State)), ("$error", state.Error));
                break;
            case AlarmRow alarm:
                var e = alarm.Event;
                Insert(
                    "INSERT INTO alarm_events (t, station, station_name, flag, event, state, class, text, user) VALUES ($t, $station, $name, $flag, $event, $state, $class, $text, $user)",
                    ("$t", HistoryTime.ToMs(e.At)), ("$station", e.Station.Address), ("$name", e.StationName), ("$flag", e.Flag.ToString()),
                    ("$event", Words.Of(e.Transition)), ("$state", Words.Of(e.State)), ("$class", Words.Of(e.Class)), ("$text", e.Text), ("$user", alarm.User));
                break;
            case AuditRow audit:
                var a = audit.Entry;
                Insert(
                    "INSERT INTO audit (t, action_id, step, action, user, port, station, target, symbol, old_value, new_value, outcome, detail) "
                    + "VALUES ($t, $id, $step, $action, $user, $port, $station, $target, $symbol, $old, $new, $outcome, $detail)",
                    ("$t", HistoryTime.ToMs(a.At)), ("$id", a.Id.ToString()), ("$step", Words.Of(a.Step)), ("$action", Words.Of(a.Action)),
                    ("$user", a.User), ("$port", a.Port), ("$station", a.Station.Address), ("$target", a.Target), ("$symbol", a.Symbol),
                    ("$old", a.OldValue), ("$new", a.NewValue), ("$outcome", a.Outcome), ("$detail", a.Detail));
                break;
            case MetaRow meta:
                Insert("INSERT OR REPLACE INTO meta (key, value) VALUES ($key, $value)", ("$key", meta.Key), ("$value", meta.Value));
                break;
            default:
                throw new ArgumentOutOfRangeException(nameof(row), row, null);
        }
    }

    private void WriteSample(SampleRow row)
    {
        if (_sample is null)
        {
            _sample = Prepare("INSERT OR REPLACE INTO samples (tag, t, value, quality) VALUES ($tag, $t, $value, $quality)", "$tag", "$t", "$value", "$quality");
        }

        _sample.Parameters[0].Value = TagId(row.Tag);
        _sample.Parameters[1].Value = HistoryTime.ToMs(row.At);
        _sample.Parameters[2].Value = row.Value is { } v ? v : DBNull.Value;
        _sample.Parameters[3].Value = (int)row.Quality;
        _sample.ExecuteNonQuery();
    }

    /// <summary>The tag's row id, made (or renamed) on first use in this database.</summary>
    private long TagId(RecordedTag tag)
    {
        if (tagIds.TryGetValue((tag.Station, tag.Address), out var id))
        {
            return id;
        }

        _tag ??= Prepare(
            "INSERT INTO tags (station, address, symbol, format) VALUES ($station, $address, $symbol, $format) "
            + "ON CONFLICT (station, address) DO UPDATE SET symbol = excluded.symbol, format = excluded.format RETURNING id",
            "$station", "$address", "$symbol", "$format");
        _tag.Parameters[0].Value = tag.Station.Address;
        _tag.Parameters[1].Value = tag.Address.ToString();
        _tag.Parameters[2].Value = tag.Symbol;
        _tag.Parameters[3].Value = Words.Of(tag.Format);
        id = (long)_tag.ExecuteScalar()!;
        tagIds[(tag.Station, tag.Address)] = id;
        return id;
    }

    private SqliteCommand Prepare(string sql, params string[] names)
    {
        var command = connection.CreateCommand();
        command.Transaction = transaction;
        command.CommandText = sql;
        foreach (var name in names)
        {
            command.Parameters.Add(new SqliteParameter { ParameterName = name });
        }

        command.Prepare();
        return command;
    }

    private void Insert(string sql, params (string Name, object? Value)[] values)
    {
        using var command = connection.CreateCommand();
        command.Transaction = transaction;
        command.CommandText = sql;
        foreach (var (name, value) in values)
        {
            command.Parameters.AddWithValue(name, value ?? DBNull.Value);
        }

        command.ExecuteNonQuery();
    }
}
