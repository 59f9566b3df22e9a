using OperatorPanel.Core.Cpu;

namespace OperatorPanel.Stl.Instructions;

/// <summary>
/// The interrupt events each CPU has (ATCH EVNT operand): CPU 221/222 0-12, 19-23, 27-33 (no HSC1/HSC2, no port 1);
/// CPU 224 0-23, 27-33 (no port 1); CPU 224XP and 226 0-33. Sources: docs/stl-instructions.md, "Interrupt events".
/// </summary>
public static class StlInterruptEvents
{
    public static bool IsOnCpu(CpuProfile cpu, long eventNumber)
    {
        ArgumentNullException.ThrowIfNull(cpu);
        return cpu.Model switch
        {
            CpuModel.Cpu221 or CpuModel.Cpu222 => eventNumber is (>= 0 and <= 12) or (>= 19 and <= 23) or (>= 27 and <= 33),
            CpuModel.Cpu224 => eventNumber is (>= 0 and <= 23) or (>= 27 and <= 33),
            CpuModel.Cpu224XP or CpuModel.Cpu226 => eventNumber is >= 0 and <= 33,
        };
    }

    /// <summary>
    /// What raises each event, as System Manual ML801761 p. 172, Table 6-50 "Priority Order for Interrupt Events" names
    /// it (docs/sources/s7200-facts.md section 5); null outside 0-33.
    /// </summary>
    public static string? Name(long eventNumber) => eventNumber switch
    {
        >= 0 and <= 7 => $"I0.{eventNumber / 2} {(eventNumber % 2 == 0 ? "rising" : "falling")} edge",
        8 => "port 0 receive character",
        9 => "port 0 transmit complete",
        10 => "timed interrupt 0 (SMB34)",
        11 => "timed interrupt 1 (SMB35)",
        12 => "HSC0 CV=PV",
        13 => "HSC1 CV=PV",
        14 => "HSC1 direction changed",
        15 => "HSC1 external reset",
        16 => "HSC2 CV=PV",
        17 => "HSC2 direction changed",
        18 => "HSC2 external reset",
        19 => "PLS0 PTO complete",
        20 => "PLS1 PTO complete",
        21 => "timer T32 CT=PT",
        22 => "timer T96 CT=PT",
        23 => "port 0 receive message complete",
        24 => "port 1 receive message complete",
        25 => "port 1 receive character",
        26 => "port 1 transmit complete",
        27 => "HSC0 direction changed",
        28 => "HSC0 external reset",
        29 => "HSC4 CV=PV",
        30 => "HSC4 direction changed",
        31 => "HSC4 external reset",
        32 => "HSC3 CV=PV",
        33 => "HSC5 CV=PV",
        _ => null,
    };

    /// <summary>"0-12, 19-23, 27-33" for the CPU's model.</summary>
    public static string RangeText(CpuProfile cpu)
    {
        ArgumentNullException.ThrowIfNull(cpu);
        return cpu.Model switch
        {
            CpuModel.Cpu221 or CpuModel.Cpu222 => "0-12, 19-23, 27-33",
            CpuModel.Cpu224 => "0-23, 27-33",
            CpuModel.Cpu224XP or CpuModel.Cpu226 => "0-33",
        };
    }
}
