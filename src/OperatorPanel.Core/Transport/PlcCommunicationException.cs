using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Core.Transport;

/// <summary>The one exception family of the link: a <see cref="Kind"/> and, where known, the <see cref="Station"/>.</summary>
public sealed class PlcCommunicationException : Exception
{
    public PlcCommunicationException(PlcErrorKind kind, Station? station, string message, Exception? innerException = null)
        : base(message, innerException)
    {
        Kind = kind;
        Station = station;
    }

    public PlcCommunicationException()
        : this(PlcErrorKind.PortUnavailable, null, "link failure")
    {
    }

    public PlcCommunicationException(string message)
        : this(PlcErrorKind.PortUnavailable, null, message)
    {
    }

    public PlcCommunicationException(string message, Exception innerException)
        : this(PlcErrorKind.PortUnavailable, null, message, innerException)
    {
    }

    public PlcErrorKind Kind { get; }

    public Station? Station { get; }
}
