namespace OperatorPanel.Core.Cpu;

/// <summary>The S7-200 CPUs the panel supports.</summary>
public enum CpuModel
{
    Cpu221,
    Cpu222,
    Cpu224,
    Cpu224XP,
    Cpu226,
}
