namespace OperatorPanel.Historian.Storage;

/// <summary>Why the historian could not read or write, in the terms the operator can act on.</summary>
public enum HistoryErrorKind
{
    /// <summary>Another program holds the database (a second panel or opanel recording the same project).</summary>
    Locked,

    /// <summary>The disk (or the user's quota) is full.</summary>
    DiskFull,

    /// <summary>The file or its folder cannot be opened or written (permissions, a read-only disk, a vanished drive).</summary>
    NotWritable,

    /// <summary>The file is damaged; SQLite can no longer read it.</summary>
    Corrupt,

    /// <summary>The file is another program's, or not SQLite at all.</summary>
    NotAHistory,

    /// <summary>A newer Operator Panel wrote it; this one reads it but never writes it.</summary>
    NewerSchema,
}
