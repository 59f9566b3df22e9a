using OperatorPanel.Simulator.Reference;

namespace OperatorPanel.Simulator.Stl;

/// <summary>
/// The communication phase of the scan (C233-01 p. 4-23: "During the message-processing phase of the scan cycle, the
/// CPU processes any messages that were received from the communications port"): raised in RUN after the program,
/// when the outputs are written, and in STOP every <see cref="StopCommunicationCycle"/>, where the ports are kept
/// running so a CPU in STOP still hears and answers its port's PPI traffic.
/// </summary>
public sealed partial class StlPlc
{
    private long _nextStopCycle;

    /// <summary>The CPU's communication phase: PPI jobs received are done now. Handlers run inside the simulated scan.</summary>
    public event EventHandler? CommunicationPhase;

    /// <summary>How often a CPU in STOP serves its communication phase (its STOP scan time is not published: an assumption).</summary>
    public TimeSpan StopCommunicationCycle { get; set; } = TimeSpan.FromMilliseconds(1);

    private void ServeCommunication()
    {
        if (CommunicationPhase is null)
        {
            return;
        }

        // Telegrams whose last character arrived before now must be known before the jobs are done.
        foreach (var port in _ports)
        {
            if (port?.NextChange is { } change && change.Ticks * 100 <= _now)
            {
                AdvancePort(port);
            }
        }

        CommunicationPhase.Invoke(this, EventArgs.Empty);
        RefreshNextChange();
    }

    /// <summary>STOP: no program, but the ports run and the communication phase comes round, until RUN again or <paramref name="end"/>.</summary>
    private void RunStopped(long end)
    {
        if (CommunicationPhase is null)
        {
            _now = Math.Max(_now, end);
            return;
        }

        var cycle = Math.Max(StopCommunicationCycle.Ticks * 100, 1);
        while (Mode == OperatingMode.Stop)
        {
            var next = _nextStopCycle;
            foreach (var port in _ports)
            {
                next = port?.NextChange is { } change ? Math.Min(next, change.Ticks * 100) : next;
            }

            if (next > end)
            {
                break;
            }

            _now = Math.Max(_now, next);
            foreach (var port in _ports)
            {
                if (port?.NextChange is { } change && change.Ticks * 100 <= _now)
                {
                    AdvancePort(port);
                }
            }

            if (_now >= _nextStopCycle)
            {
                _nextStopCycle = _now + cycle;
                CommunicationPhase?.Invoke(this, EventArgs.Empty);
            }
        }

        _now = Math.Max(_now, Mode == OperatingMode.Stop ? end : _now);
    }
}
