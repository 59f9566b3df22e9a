using OperatorPanel.Core.Transport;

namespace OperatorPanel.Simulator.Soak;

/// <summary>
/// A noisy stretch of cable between two byte pipes (the panel's and the PLC's side, each one end of a socat pty pair):
/// every chunk of characters read on one side is written to the other through that direction's
/// <see cref="FaultInjector"/>. The two directions have their own seeds derived from one, so a run is repeatable in
/// its faults (not in its timing: the pty pairs run in real time).
/// </summary>
public sealed class NoisyLineProxy(ITransport panelSide, ITransport plcSide, LineFaults faults, int seed)
{
    private static readonly TimeSpan ReadPoll = TimeSpan.FromMilliseconds(50);

    public FaultInjector ToPlc { get; } = new(faults, seed);

    public FaultInjector ToPanel { get; } = new(faults, unchecked((seed * 31) + 17));

    /// <summary>Copies both ways until cancelled; a failing side ends the run with its exception.</summary>
    public async Task RunAsync(CancellationToken cancellationToken)
    {
        await panelSide.OpenAsync(cancellationToken).ConfigureAwait(false);
        await plcSide.OpenAsync(cancellationToken).ConfigureAwait(false);
        await Task.WhenAll(
            PumpAsync(panelSide, ToPlc, plcSide, cancellationToken),
            PumpAsync(plcSide, ToPanel, panelSide, cancellationToken)).ConfigureAwait(false);
    }

    private static async Task PumpAsync(ITransport from, FaultInjector faults, ITransport to, CancellationToken cancellationToken)
    {
        var buffer = new byte[512];
        while (!cancellationToken.IsCancellationRequested)
        {
            var count = await from.ReadAsync(buffer, ReadPoll, cancellationToken).ConfigureAwait(false);
            if (count == 0)
            {
                continue;
            }

            // Each direction's injector is used by its own pump only.
            var received = faults.Pass(buffer.AsSpan(0, count));
            if (received.Length > 0)
            {
                await to.WriteAsync(received, cancellationToken).ConfigureAwait(false);
            }
        }
    }
}
