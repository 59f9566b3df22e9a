using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Line;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Link.V3;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Protocol.V3;
using OperatorPanel.Core.Transport;
using OperatorPanel.Simulator.Hosting;
using Serilog;

namespace OperatorPanel.Simulator.Soak;

/// <summary>
/// A soak run end to end: the simulated PLC (behind an <see cref="ExecutedWriteObserver"/>) on its pty, the
/// <see cref="NoisyLineProxy"/> between the two pty pairs, and the real panel stack (SerialPortTransport, V3Link, Bus
/// and its polling loop, speaking protocol v3) on the panel's pty. The <see cref="SoakField"/> changes the PLC's last
/// input and SM bytes now and then; the panel alternates, by the seed, between writing a new value to an address of the
/// <see cref="SoakRegion"/> and refreshing the region (<see cref="SoakWorkload"/>), until the duration is up; then the
/// <see cref="SoakJudge"/> holds what it showed and confirmed against what the PLC did.
/// </summary>
public static class SoakSession
{
    public static async Task<SoakFigures> RunAsync(SoakSetup setup, TimeProvider time, ILogger? log, CancellationToken cancellationToken)
    {
        ArgumentNullException.ThrowIfNull(setup);
        ArgumentNullException.ThrowIfNull(time);
        log ??= Serilog.Core.Logger.None;
        var region = setup.Region;
        var field = new SoakField(setup.Line, setup.Inputs ?? [], setup.Memory, setup.Inputs is null ? [] : FieldDriven(setup), time);
        var observer = new ExecutedWriteObserver(field, setup.Memory, Watched(setup), time);
        var initial = observer.Initial;
        var unwatched = region.Items.Where(a => !initial.Covers(a)).ToList();
        if (unwatched.Count > 0)
        {
            throw new ArgumentException($"{string.Join(", ", unwatched)}: outside the bytes the judge watches", nameof(setup));
        }

        var plcPort = new SerialPortTransport(Serial(setup, setup.PlcPort));
        var host = new SimulatedPlcHost(plcPort, observer, time, log);
        var proxyPanel = new SerialPortTransport(Serial(setup, setup.ProxyPanelSide));
        var proxyPlc = new SerialPortTransport(Serial(setup, setup.ProxyPlcSide));
        var proxy = new NoisyLineProxy(proxyPanel, proxyPlc, setup.Faults, setup.Seed);
        var panelSerial = Serial(setup, setup.PanelPort);
        var items = region.Items.Select(a => new WatchedItem(setup.Station, a));
        await using var bus = Bus.StartV3(
            new V3Link(new SerialPortTransport(panelSerial), LinkOptions.For(panelSerial), time, log),
            PollPlanner.Build(items, new Dictionary<Station, Core.Cpu.CpuProfile> { [setup.Station] = setup.Cpu }),
            new BusSettings { Mode = RefreshMode.OnDemand },
            time,
            log);

        using var stop = CancellationTokenSource.CreateLinkedTokenSource(cancellationToken);
        var running = new[]
        {
            Task.Run(() => host.RunAsync(stop.Token), stop.Token),
            Task.Run(() => proxy.RunAsync(stop.Token), stop.Token),
        };
        var started = time.GetTimestamp();
        var work = new SoakWorkload(setup, bus, time);
        try
        {
            await work.RunAsync(running, stop.Token).ConfigureAwait(false);
        }
        finally
        {
            await bus.StopPollingAsync().ConfigureAwait(false);
            await stop.CancelAsync().ConfigureAwait(false);
            await Ended(running).ConfigureAwait(false);
            await proxyPanel.DisposeAsync().ConfigureAwait(false);
            await proxyPlc.DisposeAsync().ConfigureAwait(false);
            await plcPort.DisposeAsync().ConfigureAwait(false);
        }

        var judgement = new SoakJudge(region, initial).Judge(work.Writes, work.Shown, observer.Changes, field.Settings);
        var statistics = bus.StatisticsFor(setup.Station);
        return new SoakFigures
        {
            Faults = setup.Faults.ToString(),
            Seed = setup.Seed,
            Region = region.ToString(),
            Elapsed = time.GetElapsedTime(started),
            Exchanges = statistics.Requests,
            Retries = statistics.Retries,
            Timeouts = statistics.Timeouts,
            CorruptReplies = statistics.CorruptFrames,
            NegativeReplies = statistics.NegativeReplies,
            ValuesShownGood = judgement.ValuesShownGood,
            WrongValuesShownGood = judgement.WrongValuesShownGood,
            WritesSent = judgement.WritesSent,
            WritesConfirmed = judgement.WritesConfirmed,
            ConfirmedByReadBack = judgement.ConfirmedByReadBack,
            ConfirmedAlreadyHeld = judgement.ConfirmedAlreadyHeld,
            FalseConfirmations = judgement.FalseConfirmations,
            WritesOutOfOrder = judgement.WritesOutOfOrder,
            WritesNotConfirmed = judgement.WritesNotConfirmed,
            NotConfirmedButExecuted = judgement.NotConfirmedButExecuted,
            FalseNotApplied = judgement.FalseNotApplied,
            ExecutedNeverSent = judgement.ExecutedNeverSent,
            FieldChanges = judgement.FieldChanges,
            ShownGoodByItem = judgement.ShownGoodByItem,
            ConfirmedByItem = judgement.ConfirmedByItem,
            Findings = judgement.Findings,
            CharactersOnLine = proxy.ToPlc.Characters + proxy.ToPanel.Characters,
            BitsFlipped = proxy.ToPlc.BitsFlipped + proxy.ToPanel.BitsFlipped,
            CharactersDropped = proxy.ToPlc.CharactersDropped + proxy.ToPanel.CharactersDropped,
            FramesDropped = proxy.ToPlc.FramesDropped + proxy.ToPanel.FramesDropped,
            LinesIdentified = work.Identified ? 1 : 0,
        };
    }

    private static SerialSettings Serial(SoakSetup setup, string port) => new() { PortName = port, BaudRate = setup.Baud };

    /// <summary>V below the handler's bytes, all of M, Q and I: everything a panel write may change, and what the field sets.</summary>
    private static IEnumerable<WatchedBytes> Watched(SoakSetup setup) =>
    [
        new(ProtocolArea.V, 0, setup.HandlerFirstByte),
        new(ProtocolArea.M, 0, setup.Memory.M.Length),
        new(ProtocolArea.Q, 0, setup.Memory.Q.Length),
        new(ProtocolArea.I, 0, setup.Memory.I.Length),
    ];

    /// <summary>The 4-byte window at the end of I: a list item there is widened to it, so the handler compares all four.</summary>
    private static IEnumerable<WatchedBytes> FieldDriven(SoakSetup setup) => [EndWindow(ProtocolArea.I, setup.Memory.I.Length)];

    private static WatchedBytes EndWindow(ProtocolArea area, int areaBytes) => new(area, areaBytes - HandlerShape.ItemBytes, HandlerShape.ItemBytes);

    /// <summary>Waits for the background parts to stop; their cancellation is the expected end.</summary>
    private static async Task Ended(Task[] running)
    {
        try
        {
            await Task.WhenAll(running).WaitAsync(TimeSpan.FromSeconds(5)).ConfigureAwait(false);
        }
        catch (OperationCanceledException)
        {
            // Cancelled on purpose: every part ends this way.
        }
    }
}
