using System.Collections.Immutable;
using OperatorPanel.Core.Ppi;
using OperatorPanel.Core.Transport;
using OperatorPanel.Simulator.Hosting;
using OperatorPanel.Simulator.Stl.Freeport;
using OperatorPanel.Simulator.Stl.Ppi;

namespace OperatorPanel.Cli.Bench;

/// <summary>
/// The reference line read over PPI (MODELLED by simulation): the panel's <see cref="PpiMaster"/> reads the jobs of
/// <see cref="PpiReadPlanner"/> from the simulated CPU (no handler, the user's program as time per scan), all in the
/// line's own time (<see cref="SimulatedLineTransport"/>), so the characters, the handshake and the once-per-scan
/// answer are the simulator's and the PC's parts are <see cref="PpiPcSide"/>'s. A refresh starts wherever the scan is,
/// so the figure is the mean of several refreshes run back to back.
/// </summary>
internal static class PpiBench
{
    public static async Task<PpiBenchReport> RunAsync(BenchLine line, int baud, double scanMs, int refreshes, double usbLatencyMs)
    {
        ArgumentNullException.ThrowIfNull(line);
        var ppiLine = new LineSettings(baud, Parity.Even, 8);
        var pc = PpiPcSide.For(baud, usbLatencyMs);
        var simulated = new StlLine(ppiLine);
        if (!StlStation.TryCreate(EmptyProgram.Awl, line.Cpu, 0, ppiLine, out var station, out var error))
        {
            throw new InvalidOperationException($"the bench CPU does not load: {error}");
        }

        var settings = new PpiSettings(line.Station.Address, baud);
        station.AttachPpi(settings with { StationDelay = Later(settings.StationDelay, TimeSpan.FromMilliseconds(pc.TurnaroundMs)) });
        station.Plc.UserProgramTime = TimeSpan.FromMilliseconds(scanMs);
        simulated.Attach(station, runProcess: false);
        simulated.RunUntil(TimeSpan.FromMilliseconds(50));
        var transport = new SimulatedLineTransport(simulated, ppiLine.CharacterTime / 4)
        {
            ReceiveLatency = TimeSpan.FromMilliseconds(pc.ReceiveLatencyMs),
            WriteLatency = TimeSpan.FromMilliseconds(pc.WriteLatencyMs),
            IdleBeforeWrite = ppiLine.Bits(PpiPcSide.SyncPauseBits),
        };
        var master = new PpiMaster(transport, PpiMasterOptions.ForBaud(baud), transport.Clock);
        var plan = PpiReadPlanner.Plan(line.Tags.Select(t => t.Address));
        var results = ImmutableArray.CreateBuilder<PpiRefresh>(refreshes);
        for (var i = 0; i < refreshes; i++)
        {
            var (start, chars, empty) = (simulated.Now, transport.BytesWritten + transport.BytesReceived, master.EmptyPolls);
            foreach (var request in plan.Requests)
            {
                await master.ReadAsync(line.Station, request.Items, CancellationToken.None).ConfigureAwait(false);
            }

            results.Add(new PpiRefresh(
                (simulated.Now - start).TotalMilliseconds, transport.BytesWritten + transport.BytesReceived - chars, master.EmptyPolls - empty));
        }

        return new PpiBenchReport(line, baud, scanMs, pc, plan, results.MoveToImmutable(), TrafficModels.LowerBoundAsHex(line).TotalChars);
    }

    private static TimeSpan Later(TimeSpan a, TimeSpan b) => a > b ? a : b;
}
