using Spectre.Console.Rendering;

namespace OperatorPanel.Cli.Watch;

/// <summary>
/// Where watch snapshots go. On a terminal (<paramref name="screen"/> given) the view is drawn in place by
/// Spectre.Console's live display, fitted to the terminal's size (<see cref="WatchScreen"/>), at most five times a
/// second; elsewhere (pipes, CI) and with --json each snapshot is appended whole, after every cycle when the cycles
/// are counted (--once, --cycles), else once a second.
/// </summary>
/// <param name="cli">Where to print, and whether as JSON.</param>
/// <param name="everyCycle">Counted cycles (--once, --cycles): appended after every cycle.</param>
/// <param name="time">The clock of the redraw and append intervals.</param>
/// <param name="screen">Shows one frame of the live display; null when stdout is not a terminal.</param>
/// <param name="size">The terminal's width and height now (it may be resized while watch runs).</param>
internal sealed class LiveOutput(CliContext cli, bool everyCycle, TimeProvider time, Action<IRenderable>? screen = null, Func<(int Width, int Height)>? size = null)
{
    private static readonly TimeSpan RedrawInterval = TimeSpan.FromMilliseconds(200);
    private static readonly TimeSpan AppendInterval = TimeSpan.FromSeconds(1);

    private readonly CliContext _cli = cli;
    private readonly bool _everyCycle = everyCycle;
    private readonly TimeProvider _time = time;
    private long? _lastShown;
    private bool _missed;

    private bool Redraws => screen is not null && !_cli.Json;

    /// <summary>Called after each completed cycle; shows <paramref name="snapshot"/> when the policy says it is time.</summary>
    public void CycleCompleted(Func<WatchSnapshot> snapshot)
    {
        var interval = Redraws ? RedrawInterval : AppendInterval;
        _missed = !((_everyCycle && !Redraws) || _lastShown is not { } last || _time.GetElapsedTime(last) >= interval);
        if (!_missed)
        {
            Show(snapshot());
        }
    }

    /// <summary>At the end: a redrawn view skipped its last cycles for the rate limit; show where it ended.</summary>
    public void Finish(Func<WatchSnapshot> snapshot)
    {
        if (_missed && Redraws)
        {
            Show(snapshot());
        }
    }

    private void Show(WatchSnapshot snapshot)
    {
        _lastShown = _time.GetTimestamp();
        if (_cli.Json)
        {
            _cli.WriteJsonLine(snapshot);
            return;
        }

        if (Redraws)
        {
            var (width, height) = size?.Invoke() ?? (80, 24);
            screen!(WatchScreen.Render(snapshot, width, height));
            return;
        }

        _cli.Out.Write(SnapshotRenderer.Render(snapshot) + Environment.NewLine);
        _cli.Out.Flush();
    }
}
