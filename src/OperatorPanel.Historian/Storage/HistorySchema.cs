namespace OperatorPanel.Historian.Storage;

/// <summary>
/// The database's tables, version <see cref="Version"/> (kept in SQLite's <c>PRAGMA user_version</c>), as docs/historian.md
/// documents them. Times are <see cref="HistoryTime"/> milliseconds; a tag's value is its bytes read as one unsigned
/// big-endian integer (a REAL's bits, a DINT's two's complement), decoded with the tag's address and format.
/// A version above ours is a newer program's database: it is read, never written.
/// </summary>
internal static class HistorySchema
{
    public const int Version = 1;

    /// <summary>
    /// Samples and station states are WITHOUT ROWID tables clustered on (tag, time): a trend's range is one contiguous
    /// read, and a row costs about 20 bytes on disk.
    /// </summary>
    public const string CreateV1 = """
        CREATE TABLE meta (key TEXT PRIMARY KEY, value TEXT NOT NULL);
        CREATE TABLE tags (
            id INTEGER PRIMARY KEY,
            station INTEGER NOT NULL,
            address TEXT NOT NULL,
            symbol TEXT NOT NULL,
            format TEXT NOT NULL,
            UNIQUE (station, address));
        CREATE TABLE samples (
            tag INTEGER NOT NULL,
            t INTEGER NOT NULL,
            value INTEGER,
            quality INTEGER NOT NULL,
            PRIMARY KEY (tag, t)) WITHOUT ROWID;
        CREATE TABLE station_states (
            station INTEGER NOT NULL,
            t INTEGER NOT NULL,
            state TEXT NOT NULL,
            error TEXT,
            PRIMARY KEY (station, t)) WITHOUT ROWID;
        CREATE TABLE sessions (
            id INTEGER PRIMARY KEY,
            started INTEGER NOT NULL,
            last INTEGER NOT NULL,
            ended INTEGER,
            source TEXT NOT NULL);
        CREATE TABLE alarm_events (
            id INTEGER PRIMARY KEY,
            t INTEGER NOT NULL,
            station INTEGER NOT NULL,
            station_name TEXT NOT NULL,
            flag TEXT NOT NULL,
            event TEXT NOT NULL,
            state TEXT NOT NULL,
            class TEXT NOT NULL,
            text TEXT NOT NULL,
            user TEXT);
        CREATE INDEX alarm_events_t ON alarm_events (t);
        CREATE TABLE audit (
            id INTEGER PRIMARY KEY,
            t INTEGER NOT NULL,
            action_id TEXT NOT NULL,
            step TEXT NOT NULL,
            action TEXT NOT NULL,
            user TEXT NOT NULL,
            port TEXT NOT NULL,
            station INTEGER NOT NULL,
            target TEXT,
            symbol TEXT,
            old_value TEXT NOT NULL,
            new_value TEXT NOT NULL,
            outcome TEXT,
            detail TEXT);
        CREATE INDEX audit_t ON audit (t);
        """;
}
