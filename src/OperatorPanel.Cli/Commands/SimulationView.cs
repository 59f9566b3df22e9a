using OperatorPanel.Core.Transport;
using OperatorPanel.Simulator.Reference;

namespace OperatorPanel.Cli.Commands;

/// <summary>
/// What <c>opanel simulate</c> says when it starts and when it stops (a JSON object each with --json). Cpu is the CPU
/// simulated, or the distinct CPUs in station order ("CPU 224, CPU 226") when a project's stations differ.
/// </summary>
internal sealed record SimulationView(string Cpu, IReadOnlyList<int> Stations, string Port, string Line, int ReplyDelayMs, bool Process, string Model)
{
    private readonly IReadOnlyList<string> _cpus = [];

    public SimulationView(List<HandlerConfig> configs, SerialSettings settings, bool process, string model)
        : this(
            string.Join(", ", configs.Select(c => c.Cpu.DisplayName).Distinct()),
            configs.Select(c => c.Station.Address).ToList(),
            settings.PortName,
            settings.LineText,
            configs[0].ReplyDelayMs,
            process,
            model)
    {
        _cpus = [.. configs.Select(c => c.Cpu.DisplayName)];
        PlcPort = configs[0].Port;
        Protocol = configs[0].Protocol;
        Compact = configs[0].Compact;
        EndTimeoutMs = Protocol == 3 ? configs[0].V3SetupFor(settings).EndTimeoutMs : 0;
        Stop = configs.Any(c => c.AllowStop && !(c.Protocol == 3 && c.Compact));
        Handlers = [.. configs.Select(c => (c.Protocol == 3 && c.Compact ? "compact" : "full") + (c.AllowStop && !(c.Protocol == 3 && c.Compact) ? " with STOP" : string.Empty))];
    }

    /// <summary>Each station's handler in station order: "full", "full with STOP", "compact".</summary>
    public IReadOnlyList<string> Handlers { get; init; } = [];

    /// <summary>The handlers' protocol: 3 (what the panel speaks) or 2 (simulate --protocol 2).</summary>
    public int Protocol { get; init; }

    /// <summary>Protocol 3: the compact handler (no list, no STOP).</summary>
    public bool Compact { get; init; }

    /// <summary>Protocol 3: END_TIMEOUT_MS (SMW92), the receive's end and the reply's earliest start.</summary>
    public int EndTimeoutMs { get; init; }

    /// <summary>STOP is in at least one station's handler.</summary>
    public bool Stop { get; init; }

    /// <summary>The PLC port the handlers use (--plc-port; the same for every station of one simulate).</summary>
    public int PlcPort { get; init; }

    /// <summary>The CPUs run no handler and speak PPI (simulate --ppi).</summary>
    public bool Ppi { get; init; }

    public void WriteStart(CliContext cli)
    {
        if (cli.Json)
        {
            cli.WriteJsonLine(new { @event = "started", simulation = this });
            return;
        }

        var plcs = _cpus.Distinct().Count() > 1
            ? string.Join(", ", Stations.Select((s, i) => $"station {s} ({_cpus[i]})"))
            : $"{Cpu} at station{(Stations.Count == 1 ? string.Empty : "s")} {string.Join(", ", Stations)}";
        // Stations of one project may differ (a compact CPU 221 beside a full CPU 226 with STOP): then each is named,
        // so the banner never claims STOP or a handler shape for a station that does not have it.
        var shapes = Handlers.Distinct().Count() > 1
            ? $"handlers: {string.Join(", ", Stations.Select((s, i) => $"station {s} {Handlers[i]}"))}"
            : $"{(Compact ? "compact" : "full")} handler";
        var timing = Protocol == 3
            ? $"protocol 3 {shapes}, END_TIMEOUT_MS {EndTimeoutMs}{(Stop && Handlers.Distinct().Count() == 1 ? ", STOP" : string.Empty)}"
            : $"protocol 2 handler, reply delay {ReplyDelayMs} ms";
        var handler = Ppi ? "no handler, PPI at the station addresses"
            : (PlcPort == 0 ? string.Empty : $"PLC port {PlcPort}, ") + timing;
        cli.Out.WriteLine($"simulating {plcs} on {Port} {Line}, "
            + $"{handler}, model {Model}, demo process {(Process ? "on" : "off")}; Ctrl+C to stop");
        cli.Out.Flush();
    }

    public void WriteSummary(CliContext cli, int replies, int framesReceived, int ppiFramesAnswered)
    {
        if (cli.Json)
        {
            cli.WriteJsonLine(Ppi
                ? new { @event = "stopped", port = Port, ppiTelegramsAnswered = ppiFramesAnswered }
                : (object)new { @event = "stopped", port = Port, framesReceived, framesAnswered = replies, ppiTelegramsAnswered = ppiFramesAnswered });
            return;
        }

        cli.Out.WriteLine(Ppi
            ? $"stopped serving {Port}: {ppiFramesAnswered} PPI telegrams answered"
            : $"stopped serving {Port}: {framesReceived} frames received, {replies} answered"
                + (ppiFramesAnswered > 0 ? $", {ppiFramesAnswered} PPI telegrams answered" : string.Empty));
    }
}
