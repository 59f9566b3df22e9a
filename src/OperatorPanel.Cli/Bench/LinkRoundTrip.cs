using OperatorPanel.Core.Line;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Transport;
using OperatorPanel.Simulator.Hosting;
using OperatorPanel.Simulator.Reference;

namespace OperatorPanel.Cli.Bench;

/// <summary>
/// The measured part of `opanel bench link`: the line's reference PLC served by SimulatedPlcHost on one end of a socat
/// pty pair, the panel's PlcLink and Bus (triggered mode, stored lists) on the other, and N full refreshes requested one
/// after the other, after one IDENTIFY as the panel sends on connecting (so a handler with 09 is read with it). A pty
/// does not pace characters at the baud rate, so this measures software turnaround plus the configured reply delay,
/// not line time.
/// </summary>
internal static class LinkRoundTrip
{
    public const int Baud = 38400;
    public const byte ReplyDelayMs = 5;

    /// <summary>One refresh of a few frames takes milliseconds; a stuck one must not hang the bench.</summary>
    private static readonly TimeSpan RefreshLimit = TimeSpan.FromSeconds(10);

    public static async Task<MeasuredRoundTrip> MeasureAsync(BenchLine line, int cycles, string socatPath, TimeProvider time, CancellationToken cancellationToken)
    {
        ArgumentNullException.ThrowIfNull(line);
        ArgumentOutOfRangeException.ThrowIfLessThan(cycles, 1);
        using var pty = await SocatPty.StartAsync(socatPath, time, cancellationToken).ConfigureAwait(false);
        var plc = new ReferencePlc(new HandlerConfig(line.Station, line.Cpu, replyDelayMs: ReplyDelayMs));
        Fill(plc.Memory);
        var simulator = new BusSimulator();
        simulator.Attach(plc);
        var panelSerial = new SerialSettings { PortName = pty.PanelEnd, BaudRate = Baud };
        await using var plcPort = new SerialPortTransport(panelSerial with { PortName = pty.PlcEnd });
        await plcPort.OpenAsync(cancellationToken).ConfigureAwait(false);
        var host = new SimulatedPlcHost(plcPort, simulator, [], time);
        var options = LinkOptions.For(panelSerial, ReplyDelayMs);
        using var stop = CancellationTokenSource.CreateLinkedTokenSource(cancellationToken);
        var hostRun = Task.Run(() => host.RunAsync(stop.Token), CancellationToken.None);
        await using var bus = Bus.Start(
            new PlcLink(new SerialPortTransport(panelSerial), options, time), line.Plan(), new BusSettings { Mode = RefreshMode.OnDemand }, time);
        var refreshes = new List<double>(cycles);
        var failed = 0;
        try
        {
            // As the panel does on connecting: IDENTIFY tells the bus the handler's features (09 READ CHANGES OF LISTS).
            await bus.IdentifyAsync(line.Station, cancellationToken).ConfigureAwait(false);
            for (var i = 0; i < cycles; i++)
            {
                var result = await bus.RefreshAsync(cancellationToken).WaitAsync(RefreshLimit, time, cancellationToken).ConfigureAwait(false);
                refreshes.Add((result.FinishedAt - result.StartedAt).TotalMilliseconds);
                failed += result.FramesFailed;
            }
        }
        finally
        {
            await bus.StopPollingAsync().ConfigureAwait(false);
            await stop.CancelAsync().ConfigureAwait(false);
            await StopHostAsync(hostRun).ConfigureAwait(false);
        }

        return new MeasuredRoundTrip(
            $"{Baud} 8N1, reply delay {ReplyDelayMs} ms, inter-frame gap {options.InterFrameGap.TotalMilliseconds:0} ms",
            cycles,
            bus.Plan.FrameCount,
            failed,
            bus.StatisticsFor(line.Station),
            refreshes.Min(),
            refreshes.Average(),
            refreshes.Max());
    }

    private static async Task StopHostAsync(Task hostRun)
    {
        try
        {
            await hostRun.ConfigureAwait(false);
        }
        catch (OperationCanceledException)
        {
            // The host ends its run with the cancellation: the normal way to stop it.
        }
    }

    /// <summary>Every readable byte gets a different, fixed value, so replies carry real data rather than zeros.</summary>
    private static void Fill(PlcMemory memory)
    {
        foreach (var area in new[] { memory.I, memory.Q, memory.M, memory.V })
        {
            for (var i = 0; i < area.Length; i++)
            {
                area[i] = (byte)((i * 37) + 11);
            }
        }
    }
}
