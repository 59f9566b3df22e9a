using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;

namespace OperatorPanel.Cli.Bench;

/// <summary>
/// The line `opanel bench link` prices: a CPU 226 (Current) at station 2 with all its local I/O (IB0-IB2, 24 inputs;
/// QB0-QB1, 16 outputs; read as bytes), 32 memory tags in the Memory window's four widths, 8 of each, 24 in V and 8 in M,
/// at fixed addresses scattered the way a real program scatters them (a recipe block, counters, setpoints, flags),
/// and 64 alarm bits M10.0-M17.7. Fixed and deterministic so runs can be compared; never tuned to pass the targets.
/// </summary>
internal static class ReferenceLine
{
    public static readonly ImmutableArray<(string Group, string[] Addresses)> Groups =
    [
        ("inputs", ["IB0", "IB1", "IB2"]),
        ("outputs", ["QB0", "QB1"]),

        // Recipe block VB100-VB180: number, times and quantities, with unused bytes between the fields.
        ("recipe", ["VW100", "VD104", "VD112", "VW120", "VB124", "VB130", "VD140", "VW150", "VB170", "V180.0"]),

        // Counters VB400-VB460: good and rejected parts, shift counters, status bits.
        ("counters", ["VD400", "VD408", "VW420", "VB430", "V440.2", "V440.5", "VW456"]),

        // Setpoints VB1000-VB1040: speeds, temperatures, limits.
        ("setpoints", ["VW1000", "VD1004", "VW1012", "VB1020", "VB1024", "VD1030", "V1040.1"]),

        // Flags MB0-MB9: mode bits, a step number, a timer preset, a position.
        ("flags", ["M0.0", "M0.5", "M1.2", "M1.7", "MB2", "MB3", "MW4", "MD6"]),
        ("alarms", [.. Enumerable.Range(10, 8).SelectMany(b => Enumerable.Range(0, 8).Select(bit => $"M{b}.{bit}"))]),
    ];

    public static BenchLine Create() => new(
        new Station(2),
        CpuProfiles.For(CpuModel.Cpu226, CpuRevision.Current),
        [.. Groups.SelectMany(g => g.Addresses.Select(a => new BenchTag(g.Group, PlcAddress.Parse(a))))]);
}
