using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Simulator.Hosting;
using OperatorPanel.Simulator.Reference;

namespace OperatorPanel.Simulator.Soak;

/// <summary>
/// One soak run: two pty pairs (the panel's port and the proxy's panel side; the proxy's PLC side and the PLC's
/// port), the simulated line serving <see cref="Station"/> with the PLC memory the judge watches, the faults and the
/// seed, and how long the panel works. <see cref="HandlerFirstByte"/> is the first V byte of the handler's own range:
/// the judge watches V below it (the handler's buffer changes with every frame), and all of M and Q.
/// </summary>
public sealed record SoakSetup
{
    public required string PanelPort { get; init; }

    public required string ProxyPanelSide { get; init; }

    public required string ProxyPlcSide { get; init; }

    public required string PlcPort { get; init; }

    public required int Baud { get; init; }

    public required LineFaults Faults { get; init; }

    public required int Seed { get; init; }

    public required TimeSpan Duration { get; init; }

    public required Station Station { get; init; }

    public required CpuProfile Cpu { get; init; }

    public required ISimulatedLine Line { get; init; }

    public required PlcMemory Memory { get; init; }

    public required int HandlerFirstByte { get; init; }

    public SoakRegion Region { get; init; } = SoakRegion.Default;
}
