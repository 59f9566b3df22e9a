namespace OperatorPanel.Core.Cpu;

/// <summary>
/// Hardware generation of a CPU model where the figures differ. See docs/cpu-profiles.md for the sources.
/// </summary>
public enum CpuRevision
{
    /// <summary>
    /// First CPU 22x generation as described by the older System Manual excerpted in seed 002
    /// (CPU 221/222/224 only): smaller V memory, Freeport codes 110/111 = 600/300 baud.
    /// </summary>
    Early,

    /// <summary>
    /// Later CPUs as in the S7-200 System Manual 08/2008: larger V memory, Freeport codes
    /// 110/111 = 115.2k/57.6k baud. The default.
    /// </summary>
    Current,
}
