using Serilog;
using Serilog.Core;
using Serilog.Events;

namespace OperatorPanel.Core.Tests.Polling;

/// <summary>Collects log events so tests can assert on what the engine logged (the shared CollectingSink lives in TestKit).</summary>
internal sealed class PollingLogSink : ILogEventSink
{
    private readonly Lock _lock = new();
    private readonly List<LogEvent> _events = [];

    public IReadOnlyList<LogEvent> Events
    {
        get { lock (_lock) { return [.. _events]; } }
    }

    public ILogger CreateLogger() => new LoggerConfiguration().MinimumLevel.Verbose().WriteTo.Sink(this).CreateLogger();

    public void Emit(LogEvent logEvent)
    {
        lock (_lock) { _events.Add(logEvent); }
    }

    /// <summary>The value of a scalar property, as the event carried it (strings unquoted).</summary>
    public static object? Property(LogEvent logEvent, string name) =>
        logEvent.Properties.TryGetValue(name, out var value) && value is ScalarValue scalar ? scalar.Value : null;
}
