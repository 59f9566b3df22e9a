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
