using System.Collections.Immutable;
using System.Globalization;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Core.Projects;

/// <summary>
/// A new project for one station: every local digital input and output of the CPU with a placeholder symbol,
/// no tags and no alarms, 9600 8N1 over a cable, continuous refresh, the compact handler on a CPU 221 or 222 (the
/// default offered there, <see cref="CpuProfile.OffersCompactHandler"/>). Valid as it stands; the user renames from there.
/// </summary>
public static class StarterProject
{
    public static PanelProject Create(string name, CpuProfile cpu, Station station, string portName)
    {
        ArgumentNullException.ThrowIfNull(name);
        ArgumentNullException.ThrowIfNull(cpu);
        ArgumentException.ThrowIfNullOrWhiteSpace(portName);
        var plc = new ProjectStation(
            Name: "PLC " + station.Address.ToString(CultureInfo.InvariantCulture),
            Address: station,
            Cpu: cpu,
            Link: new SerialSettings { PortName = portName },
            Inputs: LocalBits(MemoryArea.I, cpu.LocalDigitalInputs, "Input", "Local input"),
            Outputs: LocalBits(MemoryArea.Q, cpu.LocalDigitalOutputs, "Output", "Local output"),
            Tags: [],
            Alarms: [])
        {
            Compact = cpu.OffersCompactHandler,
        };
        return new PanelProject(name, RefreshSettings.Default, [plc]);
    }

    /// <summary>The CPU's on-board points are numbered from bit 0 of byte 0 upwards (I0.0-I1.5 on a CPU 224).</summary>
    private static ImmutableArray<IoSymbol> LocalBits(MemoryArea area, int count, string symbolStem, string descriptionStem) =>
    [
        .. Enumerable.Range(0, count).Select(i =>
        {
            var address = PlcAddress.ForBit(area, i / 8, i % 8);
            var symbol = string.Create(CultureInfo.InvariantCulture, $"{symbolStem}_{i / 8}_{i % 8}");
            return new IoSymbol(symbol, address, $"{descriptionStem} {address}");
        }),
    ];
}
