using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Simulator.Hosting;
using OperatorPanel.Simulator.Reference;

namespace OperatorPanel.Simulator.Soak;

/// <summary>
/// One soak run: two pty pairs (the panel's port and the proxy's panel side; the proxy's PLC side and the PLC's
/// port), the simulated line serving <see cref="Station"/> with the PLC memory the judge watches, the faults and the
/// seed, and how long the panel works. <see cref="HandlerFirstByte"/> is the first V byte of the handler's own range:
/// the judge watches V below it (the handler's buffer changes with every frame), all of M, Q and I, and the end of SM.
/// </summary>
public sealed record SoakSetup
{
    private readonly SoakRegion? _region;

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

    /// <summary>
    /// The CPU's physical inputs, which the field sets (<see cref="SoakField"/>): the STL CPU's input image, copied into I
    /// at each scan, or the reference model's I itself. Null: nothing changes I and the last SM bytes; they are still
    /// watched and judged.
    /// </summary>
    public byte[]? Inputs { get; init; }

    /// <summary>What the panel watches and writes; by default <see cref="SoakRegion.AreaEnds"/> of the CPU and handler.</summary>
    public SoakRegion Region
    {
        get => _region ?? SoakRegion.AreaEnds(Cpu, HandlerFirstByte);
        init => _region = value;
    }
}
