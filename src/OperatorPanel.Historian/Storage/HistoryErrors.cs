using Microsoft.Data.Sqlite;

namespace OperatorPanel.Historian.Storage;

/// <summary>
/// Turns what SQLite and the file system throw into a <see cref="HistoryException"/> with a kind and our words, at the
/// one boundary where the database is touched (SQLite's primary result codes: sqlite.org/rescode.html).
/// </summary>
internal static class HistoryErrors
{
    public static bool IsEnvironmental(Exception ex) =>
        ex is SqliteException or IOException or UnauthorizedAccessException or HistoryException;

    public static HistoryException Translate(Exception ex, string path)
    {
        if (ex is HistoryException known)
        {
            return known;
        }

        var kind = ex switch
        {
            SqliteException { SqliteErrorCode: 5 or 6 } => HistoryErrorKind.Locked, // SQLITE_BUSY, SQLITE_LOCKED
            SqliteException { SqliteErrorCode: 13 } => HistoryErrorKind.DiskFull, // SQLITE_FULL
            SqliteException { SqliteErrorCode: 11 } => HistoryErrorKind.Corrupt, // SQLITE_CORRUPT
            SqliteException { SqliteErrorCode: 26 } => HistoryErrorKind.NotAHistory, // SQLITE_NOTADB
            IOException io when IsDiskFull(io) => HistoryErrorKind.DiskFull,
            _ => HistoryErrorKind.NotWritable, // SQLITE_CANTOPEN, SQLITE_READONLY, SQLITE_IOERR, access denied
        };
        var words = kind switch
        {
            HistoryErrorKind.Locked => "it is locked by another program (another panel or opanel recording the same project?)",
            HistoryErrorKind.DiskFull => "the disk is full",
            HistoryErrorKind.Corrupt => "the file is damaged",
            HistoryErrorKind.NotAHistory => "the file is not a history database",
            HistoryErrorKind.NewerSchema or HistoryErrorKind.NotWritable => "it cannot be opened or written",
        };
        return new HistoryException(kind, $"The history database {path}: {words} ({Detail(ex)})", ex);
    }

    /// <summary>ERROR_DISK_FULL (0x70) and ERROR_HANDLE_DISK_FULL (0x27) on Windows; ENOSPC (28) on Linux.</summary>
    private static bool IsDiskFull(IOException io) => (io.HResult & 0xFFFF) is 0x70 or 0x27 or 28;

    private static string Detail(Exception ex) => ex is SqliteException sqlite ? $"SQLite {sqlite.SqliteErrorCode}: {sqlite.Message}" : ex.Message;
}
