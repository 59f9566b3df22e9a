using OperatorPanel.Simulator.Reference;
using OperatorPanel.Simulator.Stl.Execution;

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
        _m.Events.AdvancePorts(_m.Time.Now);
        CommunicationPhase.Invoke(this, EventArgs.Empty);
        _m.Events.Refresh();
    }

    /// <summary>STOP: no program, but the ports run and the communication phase comes round, until RUN again or <paramref name="end"/>.</summary>
    private void RunStopped(long end)
    {
        var time = _m.Time;
        if (CommunicationPhase is null)
        {
            time.Now = Math.Max(time.Now, end);
            return;
        }

        var cycle = Math.Max(StlTime.FromTimeSpan(StopCommunicationCycle), 1);
        while (Mode == OperatingMode.Stop)
        {
            var next = Math.Min(_nextStopCycle, _m.Events.NextPortChange);
            if (next > end)
            {
                break;
            }

            time.Now = Math.Max(time.Now, next);
            _m.Events.AdvancePorts(time.Now);
            if (time.Now >= _nextStopCycle)
            {
                _nextStopCycle = time.Now + cycle;
                CommunicationPhase?.Invoke(this, EventArgs.Empty);
            }
        }

        time.Now = Math.Max(time.Now, Mode == OperatingMode.Stop ? end : time.Now);
    }
}
