namespace OperatorPanel.Historian.Storage;

/// <summary>The historian's one failure type: a kind the operator can act on and a message in our words.</summary>
public sealed class HistoryException : Exception
{
    public HistoryException(HistoryErrorKind kind, string message, Exception? inner = null)
        : base(message, inner) => Kind = kind;

    public HistoryException()
        : this(HistoryErrorKind.NotWritable, "the history database failed")
    {
    }

    public HistoryException(string message)
        : this(HistoryErrorKind.NotWritable, message)
    {
    }

    public HistoryException(string message, Exception innerException)
        : this(HistoryErrorKind.NotWritable, message, innerException)
    {
    }

    public HistoryErrorKind Kind { get; }
}
