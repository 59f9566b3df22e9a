using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Transport;
using OperatorPanel.Simulator.Hosting;

namespace OperatorPanel.Cli.Link;

/// <summary>Where a link verb talks to: one station on a serial line, or on the in-process demo line.</summary>
/// <param name="Station">The PLC's RS-485 station address.</param>
/// <param name="Serial">The port and its Freeport settings; for the demo line only the name and timing matter.</param>
/// <param name="Cpu">The station's CPU when known (--cpu, or the demo's); addresses are then checked against it.</param>
/// <param name="Demo">True for the in-process simulated PLC.</param>
/// <param name="ScanAllowance">The PLC scan time the reply timeout allows for (--scan-ms).</param>
/// <param name="Model">With --demo, what answers as the PLC (--model).</param>
/// <param name="NotesFile">With --project, the technician notes generate writes for the station ("Filler-README.txt"); else null.</param>
internal sealed record LinkTarget(
    Station Station, SerialSettings Serial, CpuProfile? Cpu, bool Demo, TimeSpan ScanAllowance, SimulationModel Model = SimulationModel.Stl, string? NotesFile = null)
{
    /// <summary>
    /// With --project, the station's "compact": its handler is the compact one, whose own V bytes a write may not touch
    /// and which a --demo simulates (as the panel's demo line does).
    /// </summary>
    public bool Compact { get; init; }

    /// <summary>With --project, the station's "handlerVFirst": where its handler's V bytes start (null: the top of V), which a --demo simulates too.</summary>
    public int? HandlerVFirst { get; init; }

    public string Describe() => $"{Station} on {Serial.PortName}";
}
