namespace OperatorPanel.Cli.Watch;

/// <summary>
/// Where watch snapshots go. On a terminal the view is redrawn in place (cursor home, clear) at most five times a
/// second; elsewhere (pipes, CI) and with --json each snapshot is appended, after every cycle when the cycles are
/// counted (--once, --cycles), else once a second.
/// </summary>
internal sealed class LiveOutput
{
    private static readonly TimeSpan RedrawInterval = TimeSpan.FromMilliseconds(200);
    private static readonly TimeSpan AppendInterval = TimeSpan.FromSeconds(1);
    private const string HomeAndClear = "\u001b[H\u001b[J";

    private readonly CliContext _cli;
    private readonly bool _everyCycle;
    private readonly TimeProvider _time;
    private long? _lastShown;
    private bool _missed;

    public LiveOutput(CliContext cli, bool everyCycle, TimeProvider time)
    {
        _cli = cli;
        _everyCycle = everyCycle;
        _time = time;
    }

    private bool Redraws => _cli.IsTerminal && !_cli.Json;

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

        var text = SnapshotRenderer.Render(snapshot);
        _cli.Out.Write(Redraws ? HomeAndClear + text : text + Environment.NewLine);
        _cli.Out.Flush();
    }
}
