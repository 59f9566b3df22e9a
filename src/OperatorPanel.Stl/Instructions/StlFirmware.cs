namespace OperatorPanel.Stl.Instructions;

/// <summary>Which CPUs have an instruction: all of the 22x family, or only those with CPU firmware 2.0 or later.</summary>
public enum StlFirmware
{
    /// <summary>Every CPU 221-226 (both revisions the project models).</summary>
    All,

    /// <summary>CPU firmware 2.0 and later (Micro/WIN 4.0): the <see cref="OperatorPanel.Core.Cpu.CpuRevision.Current"/> CPUs only.</summary>
    Version2,
}
