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
    }

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
        var handler = Ppi ? "no handler, PPI at the station addresses"
            : (PlcPort == 0 ? string.Empty : $"PLC port {PlcPort}, ") + $"reply delay {ReplyDelayMs} ms";
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
