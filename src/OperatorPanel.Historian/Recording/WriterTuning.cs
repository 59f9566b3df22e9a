using Microsoft.Data.Sqlite;

namespace OperatorPanel.Historian.Recording;

/// <summary>
/// What tests set on a writer: the shortest wait for a locked database (1 s, the provider's smallest; the default waits
/// <see cref="Storage.HistoryDatabase.BusyWait"/>),
/// and a hook on each connection it opens (a page limit stands in for a full disk).
/// </summary>
internal sealed record WriterTuning(TimeSpan? BusyWait = null, Action<SqliteConnection>? OnOpened = null);
