using System.Diagnostics;
using Serilog;

namespace OperatorPanel.App.Services;

/// <summary>
/// WPF reports a binding it cannot resolve (a misspelt property, a wrong type) only on its trace source, which nobody
/// reads outside a debugger; the binding then silently shows nothing. This listener writes each of those reports to
/// the panel's log as "WPF binding error: ..." (warnings and errors only), so a broken view is found in the log and
/// installer/wine-smoke.sh fails on it.
/// </summary>
public sealed class BindingErrorLog(ILogger log) : TraceListener
{
    public const string Prefix = "WPF binding error";

    public static void Attach(ILogger log)
    {
        PresentationTraceSources.Refresh();
        PresentationTraceSources.DataBindingSource.Listeners.Add(new BindingErrorLog(log));
        PresentationTraceSources.DataBindingSource.Switch.Level = SourceLevels.Warning;
    }

    public override void Write(string? message)
    {
        // WPF writes the source name first, then the message with WriteLine; only whole messages are logged.
    }

    public override void WriteLine(string? message) => log.Warning(Prefix + ": {Message}", message);
}
