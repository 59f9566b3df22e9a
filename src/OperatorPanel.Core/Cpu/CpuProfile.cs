using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Core.Cpu;

/// <summary>
/// The figures of one CPU model and revision that the panel, the protocol handler and the generator rely on.
/// Every figure is sourced in docs/cpu-profiles.md.
/// </summary>
public sealed record CpuProfile
{
    public required CpuModel Model { get; init; }

    public required CpuRevision Revision { get; init; }

    /// <summary>The manual's name, e.g. "CPU 224XP".</summary>
    public required string Name { get; init; }

    public required int LocalDigitalInputs { get; init; }

    public required int LocalDigitalOutputs { get; init; }

    public required int LocalAnalogInputs { get; init; }

    public required int LocalAnalogOutputs { get; init; }

    public required int MaxExpansionModules { get; init; }

    /// <summary>
    /// Program memory in bytes with run mode edit enabled: the smaller of the manual's two figures, taken as the room a
    /// program has because a PLC programmer may use run mode edit (CPU 224: 8192 bytes, 12288 without).
    /// </summary>
    public required int ProgramBytes { get; init; }

    /// <summary>
    /// The compact protocol 3 handler is the default offered for this CPU: the CPUs with 4096 bytes of program memory
    /// (CPU 221, 222), where the full handler's upper size estimate is more than half of it (STL050). The project
    /// wizard's Link step and <c>opanel project new</c> start from it; the user may choose the full handler.
    /// </summary>
    public bool OffersCompactHandler => ProgramBytes <= 4096;

    /// <summary>Program memory in bytes without run mode edit (the same as <see cref="ProgramBytes"/> on CPU 221/222 and Early CPUs).</summary>
    public required int ProgramBytesWithoutRunModeEdit { get; init; }

    /// <summary>Byte-addressable areas present on this CPU (I, Q, M, V, SM, S, L, and AI/AQ where it has analog).</summary>
    public required ImmutableArray<CpuArea> Areas { get; init; }

    /// <summary>SMB0 up to this count minus one are read-only system status bytes (SMB0-SMB29).</summary>
    public int ReadOnlySmBytes { get; init; } = 30;

    public int Timers { get; init; } = 256;

    public int Counters { get; init; } = 256;

    public required int HighSpeedCounters { get; init; }

    public int Accumulators { get; init; } = 4;

    /// <summary>L memory per program organisation unit (LB0-LB63).</summary>
    public int LocalBytesPerPou { get; init; } = 64;

    public required int Subroutines { get; init; }

    public int InterruptRoutines { get; init; } = 128;

    public required int CommunicationPorts { get; init; }

    public required ImmutableArray<FreeportBaudRate> FreeportBaudRates { get; init; }

    /// <summary>Value of SMB6 bits 4-7 (the CPU type nibble), shifted into place: SMB6 AND 16#F0.</summary>
    public required byte CpuIdCode { get; init; }

    public string DisplayName => Revision == CpuRevision.Current ? Name : $"{Name} (early)";

    public bool TryGetArea(MemoryArea area, out CpuArea range)
    {
        foreach (var candidate in Areas)
        {
            if (candidate.Area == area)
            {
                range = candidate;
                return true;
            }
        }

        range = null!;
        return false;
    }

    /// <summary>The SMB30/SMB130 baud code for <paramref name="baud"/>, or null where this CPU cannot run Freeport at that rate.</summary>
    public int? FreeportBaudCode(int baud)
    {
        foreach (var rate in FreeportBaudRates)
        {
            if (rate.Baud == baud)
            {
                return rate.Code;
            }
        }

        return null;
    }
}
