using System.Diagnostics.CodeAnalysis;
using OperatorPanel.Core.Audit;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Transport;
using OperatorPanel.Core.Writes;
using OperatorPanel.Simulator.Hosting;
using OperatorPanel.Simulator.Reference;
using Serilog;

namespace OperatorPanel.Cli.Link;

/// <summary>One bus opened for a verb: a <see cref="PlcLink"/> over a serial port, or over an in-process <see cref="DemoLine"/>.</summary>
internal sealed class LinkSession : IAsyncDisposable
{
    private readonly DemoLine? _demo;

    private LinkSession(PlcLink link, DemoLine? demo)
    {
        Link = link;
        _demo = demo;
    }

    public PlcLink Link { get; }

    public string PortName => Link.PortName;

    /// <summary>
    /// Opens <paramref name="serial"/>, or with <paramref name="demoStations"/> a demo line simulating them with
    /// <paramref name="model"/>; false with the reason when the demo line cannot simulate a station.
    /// </summary>
    public static bool TryOpen(
        SerialSettings serial, IReadOnlyList<HandlerConfig>? demoStations, SimulationModel model, ILogger log,
        TimeSpan? scanAllowance, [NotNullWhen(true)] out LinkSession? session, [NotNullWhen(false)] out string? error)
    {
        session = null;
        DemoLine? demo = null;
        if (demoStations is not null && !DemoLine.TryStart(serial, demoStations, model, log, out demo, out error))
        {
            return false;
        }

        ITransport transport = demo is null ? new SerialPortTransport(serial, log) : demo.PanelSide;
        session = new LinkSession(new PlcLink(transport, OptionsFor(serial, scanAllowance, demo is not null), TimeProvider.System, log), demo);
        error = null;
        return true;
    }

    /// <summary>The medium's link options, with the scan time allowed for (--scan-ms) and, on a demo line, its host allowance.</summary>
    public static LinkOptions OptionsFor(SerialSettings serial, TimeSpan? scanAllowance, bool demo)
    {
        var options = LinkOptions.For(serial);
        options = scanAllowance is { } scan ? options with { ScanAllowance = scan } : options;
        return demo ? options with { ScanAllowance = options.ScanAllowance + DemoLine.HostAllowance } : options;
    }

    public static bool TryOpen(LinkTarget target, ILogger log, [NotNullWhen(true)] out LinkSession? session, [NotNullWhen(false)] out string? error) =>
        TryOpen(target.Serial, target.Demo ? [DemoStation(target)] : null, target.Model, log, target.ScanAllowance, out session, out error);

    /// <summary>The --demo PLC: the target's station and CPU, its handler with STOP so <c>opanel stop --demo</c> can be tried.</summary>
    private static HandlerConfig DemoStation(LinkTarget target) => new(target.Station, target.Cpu!, allowStop: true);

    /// <summary>Where this session's writes and STOPs go on record: the journal, with this port and the user.</summary>
    public AuditContext AuditFor(CliContext cli) => new(cli.Journal, PortName, AuditUser.Current);

    /// <summary>
    /// Settles the writes and STOPs that earlier programs left cut short on this port (UnfinishedWrites: read back,
    /// recorded as resolved at start) and says each on stderr, so a technician learns what a killed write did.
    /// </summary>
    public async Task ResolveCutShortAsync(CliContext cli, CancellationToken cancellationToken)
    {
        var (resolved, problem) = await UnfinishedWrites.ResolveAsync(cli.Journal, Link, PortName, TimeProvider.System, cli.Log, cancellationToken);
        if (problem is not null)
        {
            cli.Error.WriteLine($"opanel: {problem}");
        }

        foreach (var entry in resolved)
        {
            cli.Error.WriteLine("opanel: " + entry.Describe());
        }
    }

    public async ValueTask DisposeAsync()
    {
        if (_demo is not null)
        {
            await _demo.DisposeAsync();
        }

        await Link.DisposeAsync();
    }
}
