using Serilog;
using Serilog.Core;
using Serilog.Events;

namespace OperatorPanel.TestKit;

/// <summary>A Serilog sink keeping every event, so tests assert on what was logged (Serilog's own test fake).</summary>
public sealed class CollectingSink : ILogEventSink
{
    private readonly Lock _lock = new();
    private readonly List<LogEvent> _events = [];

    public IReadOnlyList<LogEvent> Events
    {
        get
        {
            lock (_lock)
            {
                return [.. _events];
            }
        }
    }

    /// <summary>The rendered messages, in order.</summary>
    public IReadOnlyList<string> Messages => Events.Select(e => e.RenderMessage(System.Globalization.CultureInfo.InvariantCulture)).ToList();

    /// <summary>A logger writing every level to a new sink.</summary>
    public static (ILogger Logger, CollectingSink Sink) CreateLogger()
    {
        var sink = new CollectingSink();
        var logger = new LoggerConfiguration().MinimumLevel.Verbose().WriteTo.Sink(sink).CreateLogger();
        return (logger, sink);
    }

    public void Emit(LogEvent logEvent)
    {
        lock (_lock)
        {
            _events.Add(logEvent);
        }
    }
}
