using System.Diagnostics.CodeAnalysis;
using OperatorPanel.Core.Line;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Link.V3;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Ppi;
using OperatorPanel.Core.Transport;
using OperatorPanel.Demo;
using OperatorPanel.Simulator.Reference;

namespace OperatorPanel.Cli.Link;

/// <summary>
/// One bus opened for a verb: a <see cref="Core.Line.Bus"/> polling on demand with plain READs, over a serial port or an
/// in-process <see cref="DemoLine"/>. IDENTIFY, STOP, reads and writes all go through the bus's queue; its writes and
/// STOPs go on record in the write journal (<see cref="CliContext.Journal"/>).
/// </summary>
internal sealed class LinkSession : IAsyncDisposable
{
    private readonly DemoLine? _demo;

    private LinkSession(Bus bus, DemoLine? demo)
    {
        Bus = bus;
        _demo = demo;
    }

    public Bus Bus { get; }

    public string PortName => Bus.PortName;

    /// <summary>
    /// Opens the target's port, or with <c>--demo</c> a demo line simulating its station, and a bus watching
    /// <paramref name="plan"/> on it, logging to <c>cli.Log</c> and keeping its writes and STOPs on record in
    /// <c>cli.Journal</c>; false with the reason when the demo line cannot simulate the station.
    /// </summary>
    public static bool TryOpen(LinkTarget target, PollPlan plan, CliContext cli, [NotNullWhen(true)] out LinkSession? session, [NotNullWhen(false)] out string? error)
    {
        ArgumentNullException.ThrowIfNull(target);
        ArgumentNullException.ThrowIfNull(cli);
        var log = cli.Log;
        session = null;
        DemoLine? demo = null;
        if (target.Demo && !DemoLine.TryStart(target.Serial, [DemoStation(target)], target.Model, log, out demo, out error))
        {
            return false;
        }

        ITransport transport = demo is null ? new SerialPortTransport(target.Serial, log) : demo.PanelSide;
        var bus = target.Serial.Protocol == LinkProtocol.Ppi
            ? Bus.StartPpi(
                new PpiLink(transport, PpiOptionsFor(target.Serial, target.ScanAllowance, demo is not null), TimeProvider.System, log),
                plan, BusSettings.OnDemand with { Audit = cli.Journal }, TimeProvider.System, log)
            : Bus.OnDemand(new V3Link(transport, OptionsFor(target.Serial, target.ScanAllowance, demo is not null), TimeProvider.System, log), plan, TimeProvider.System, log, cli.Journal);
        session = new LinkSession(bus, demo);
        error = null;
        return true;
    }

    /// <summary>The medium's protocol v3 link options, with the scan time allowed for (--scan-ms) and, on a demo line, its host allowance.</summary>
    public static LinkOptions OptionsFor(SerialSettings serial, TimeSpan? scanAllowance, bool demo)
    {
        var options = V3LinkOptions.For(serial);
        if (scanAllowance is { } scan)
        {
            // Raised above the default for a long program: each of the handler's scans for a request may take that
            // long too (docs/protocol.md section 7).
            var perScan = scan > options.ScanAllowance && scan > options.HandlerScanAllowance ? scan : options.HandlerScanAllowance;
            options = options with { ScanAllowance = scan, HandlerScanAllowance = perScan };
        }

        return demo ? options with { ScanAllowance = options.ScanAllowance + DemoLine.HostAllowance } : options;
    }

    /// <summary>
    /// A PPI bus's master options: the polls wait out the scan time allowed for (--scan-ms, default 100 ms) on top of the
    /// master's second; each answer may start 300 ms late rather than 100 (a USB adapter's latency, a loaded PC: a
    /// real CPU answers within characters); on a demo line the host allowance is added to both.
    /// </summary>
    public static PpiMasterOptions PpiOptionsFor(SerialSettings serial, TimeSpan? scanAllowance, bool demo)
    {
        ArgumentNullException.ThrowIfNull(serial);
        var options = PpiMasterOptions.ForBaud(serial.BaudRate);
        var host = demo ? DemoLine.HostAllowance : TimeSpan.Zero;
        return options with
        {
            ReplyTimeout = TimeSpan.FromMilliseconds(300) + host,
            AnswerTimeout = options.AnswerTimeout + (scanAllowance ?? TimeSpan.FromMilliseconds(100)) + host,
        };
    }

    /// <summary>
    /// The --demo PLC: the target's station and CPU, its handler with STOP so <c>opanel stop --demo</c> can be tried, or
    /// for a project's compact station the compact handler (which has no STOP), so the demo keeps the V bytes the write
    /// rules keep; at the project's "handlerVFirst" when it has one.
    /// </summary>
    private static HandlerConfig DemoStation(LinkTarget target) =>
        new(target.Station, target.Cpu!, allowStop: !target.Compact) { Compact = target.Compact, V3First = target.HandlerVFirst };

    /// <summary>
    /// Settles the writes and STOPs that earlier programs left cut short on this port (through the bus's queue,
    /// Writes/UnfinishedWrites: read back, recorded as resolved at start) and says each on stderr, so a technician learns
    /// what a killed write did.
    /// </summary>
    public async Task ResolveCutShortAsync(CliContext cli, CancellationToken cancellationToken)
    {
        ArgumentNullException.ThrowIfNull(cli);
        var (resolved, problem) = await Bus.SettleCutShortAsync(cli.Journal, cancellationToken);
        if (problem is not null)
        {
            cli.Error.WriteLine($"opanel: {problem}");
        }

        foreach (var entry in resolved)
        {
            cli.Error.WriteLine("opanel: " + entry.Describe());
        }
    }

    /// <summary>The bus stops polling, then the demo line, then the port closes (the demo would see an unplugged line otherwise).</summary>
    public async ValueTask DisposeAsync()
    {
        await Bus.StopPollingAsync();
        if (_demo is not null)
        {
            await _demo.DisposeAsync();
        }

        await Bus.DisposeAsync();
    }
}
