using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Core.Cpu;

/// <summary>
/// The catalogue of supported CPUs. Figures and their sources: docs/cpu-profiles.md
/// ("S7-200 System Manual 08/2008" for Current; seed 002 Tables 1-1, A-2..A-4, C-7, C-11 for Early).
/// </summary>
public static class CpuProfiles
{
    /// <summary>SMB30 codes 000-101 are the same on every revision (seed 002, Table C-11).</summary>
    private static readonly FreeportBaudRate[] CommonRates =
    [
        new(1200, 0b101), new(2400, 0b100), new(4800, 0b011), new(9600, 0b010), new(19200, 0b001), new(38400, 0b000),
    ];

    /// <summary>Early CPUs: 110 = 600 baud, 111 = 300 baud (seed 002, Table C-11).</summary>
    private static readonly ImmutableArray<FreeportBaudRate> EarlyRates =
        [new(300, 0b111), new(600, 0b110), .. CommonRates];

    /// <summary>Current CPUs: 110 = 115.2 kbaud, 111 = 57.6 kbaud (System Manual 08/2008, SMB30 table).</summary>
    private static readonly ImmutableArray<FreeportBaudRate> CurrentRates =
        [.. CommonRates, new(57600, 0b111), new(115200, 0b110)];

    /// <summary>
    /// Program memory in bytes, with and without run mode edit: Current from the System Manual 08/2008 Table 1-1, Early
    /// from seed 002 Table 1-1 ("Program 2048 / 2048 / 4096 words"; that edition has no run mode edit, so both figures
    /// are the same). docs/cpu-profiles.md.
    /// </summary>
    public static ImmutableArray<CpuProfile> All { get; } =
    [
        Make(CpuModel.Cpu221, CpuRevision.Early, io: (6, 4, 0, 0), program: (4096, 4096), modules: 0, vBytes: 2048, smBytes: 180, analogBytes: 0, hsc: 4, sbr: 64, ports: 1, id: 0x60),
        Make(CpuModel.Cpu221, CpuRevision.Current, io: (6, 4, 0, 0), program: (4096, 4096), modules: 0, vBytes: 2048, smBytes: 180, analogBytes: 0, hsc: 4, sbr: 64, ports: 1, id: 0x60),
        Make(CpuModel.Cpu222, CpuRevision.Early, io: (8, 6, 0, 0), program: (4096, 4096), modules: 2, vBytes: 2048, smBytes: 300, analogBytes: 32, hsc: 4, sbr: 64, ports: 1, id: 0x00),
        Make(CpuModel.Cpu222, CpuRevision.Current, io: (8, 6, 0, 0), program: (4096, 4096), modules: 2, vBytes: 2048, smBytes: 300, analogBytes: 32, hsc: 4, sbr: 64, ports: 1, id: 0x00),
        Make(CpuModel.Cpu224, CpuRevision.Early, io: (14, 10, 0, 0), program: (8192, 8192), modules: 7, vBytes: 5120, smBytes: 550, analogBytes: 32, hsc: 6, sbr: 64, ports: 1, id: 0x20),
        Make(CpuModel.Cpu224, CpuRevision.Current, io: (14, 10, 0, 0), program: (8192, 12288), modules: 7, vBytes: 8192, smBytes: 550, analogBytes: 64, hsc: 6, sbr: 64, ports: 1, id: 0x20),
        Make(CpuModel.Cpu224XP, CpuRevision.Current, io: (14, 10, 2, 1), program: (12288, 16384), modules: 7, vBytes: 10240, smBytes: 550, analogBytes: 64, hsc: 6, sbr: 128, ports: 2, id: 0x20),
        Make(CpuModel.Cpu226, CpuRevision.Current, io: (24, 16, 0, 0), program: (16384, 24576), modules: 7, vBytes: 10240, smBytes: 550, analogBytes: 64, hsc: 6, sbr: 128, ports: 2, id: 0x90),
    ];

    /// <summary>The profile of a model; the revision defaults to Current, the one on sale in the last manual.</summary>
    public static CpuProfile For(CpuModel model, CpuRevision revision = CpuRevision.Current) =>
        TryFor(model, revision, out var profile)
            ? profile
            : throw new ArgumentException($"{CpuModelNames.Format(model)} has no {revision} revision", nameof(revision));

    public static bool TryFor(CpuModel model, CpuRevision revision, out CpuProfile profile)
    {
        foreach (var candidate in All)
        {
            if (candidate.Model == model && candidate.Revision == revision)
            {
                profile = candidate;
                return true;
            }
        }

        profile = null!;
        return false;
    }

    public static IEnumerable<CpuRevision> RevisionsOf(CpuModel model) =>
        All.Where(p => p.Model == model).Select(p => p.Revision);

    private static CpuProfile Make(
        CpuModel model, CpuRevision revision, (int In, int Out, int AnalogIn, int AnalogOut) io, (int WithRunModeEdit, int WithoutRunModeEdit) program, int modules,
        int vBytes, int smBytes, int analogBytes, int hsc, int sbr, int ports, byte id)
    {
        var areas = ImmutableArray.CreateBuilder<CpuArea>();
        areas.Add(new CpuArea(MemoryArea.I, 16));
        areas.Add(new CpuArea(MemoryArea.Q, 16));
        areas.Add(new CpuArea(MemoryArea.M, 32));
        areas.Add(new CpuArea(MemoryArea.V, vBytes));
        areas.Add(new CpuArea(MemoryArea.SM, smBytes));
        areas.Add(new CpuArea(MemoryArea.S, 32));
        areas.Add(new CpuArea(MemoryArea.L, 64));
        if (analogBytes > 0)
        {
            areas.Add(new CpuArea(MemoryArea.AI, analogBytes));
            areas.Add(new CpuArea(MemoryArea.AQ, analogBytes));
        }

        return new CpuProfile
        {
            Model = model,
            Revision = revision,
            Name = CpuModelNames.Format(model),
            LocalDigitalInputs = io.In,
            LocalDigitalOutputs = io.Out,
            LocalAnalogInputs = io.AnalogIn,
            LocalAnalogOutputs = io.AnalogOut,
            MaxExpansionModules = modules,
            ProgramBytes = program.WithRunModeEdit,
            ProgramBytesWithoutRunModeEdit = program.WithoutRunModeEdit,
            Areas = areas.ToImmutable(),
            HighSpeedCounters = hsc,
            Subroutines = sbr,
            CommunicationPorts = ports,
            FreeportBaudRates = revision == CpuRevision.Early ? EarlyRates : CurrentRates,
            CpuIdCode = id,
        };
    }
}
