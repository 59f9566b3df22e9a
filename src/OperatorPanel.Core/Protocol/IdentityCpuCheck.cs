using OperatorPanel.Core.Cpu;

namespace OperatorPanel.Core.Protocol;

/// <summary>
/// Whether an IDENTIFY reply fits the CPU the panel expects at that station (the project's, or --cpu): the CPU type the
/// PLC reports in SMB6 and the CPU the handler was generated for. <c>opanel identify --cpu</c> prints the mismatch; STOP
/// is not sent on one (a STOP meant for another station's CPU must not stop this one).
/// </summary>
public static class IdentityCpuCheck
{
    /// <summary>The PLC's CPU, or "an unknown CPU", from the handler's CPU code (the model it was generated for).</summary>
    public static CpuModel? GeneratedFor(IdentifyResponse reply)
    {
        ArgumentNullException.ThrowIfNull(reply);
        return Enum.GetValues<CpuModel>().Where(m => HandlerIdentity.CpuModelCode(m) == reply.CpuModelCode).Select(m => (CpuModel?)m).FirstOrDefault();
    }

    /// <summary>"CPU 224 or CPU 224XP": what SMB6's CPU type code says, or "unknown CPU type".</summary>
    public static string Smb6Means(byte smb6)
    {
        var code = (byte)(smb6 & 0xF0);
        var models = CpuProfiles.All.Where(p => p.CpuIdCode == code).Select(p => CpuModelNames.Format(p.Model)).Distinct().ToList();
        return models.Count == 0 ? "unknown CPU type" : string.Join(" or ", models);
    }

    /// <summary>
    /// Null when the reply fits <paramref name="expected"/>; else every difference in words. CPU 224 and 224XP share
    /// SMB6 16#20 (docs/cpu-profiles.md), so SMB6 is compared by code only; the handler's own CPU code names the exact
    /// model it was generated for.
    /// </summary>
    public static string? Mismatch(CpuProfile expected, IdentifyResponse reply)
    {
        ArgumentNullException.ThrowIfNull(expected);
        ArgumentNullException.ThrowIfNull(reply);
        var problems = new List<string>();
        var cpuId = (byte)(reply.Smb6 & 0xF0);
        if (cpuId != expected.CpuIdCode)
        {
            problems.Add($"the PLC reports SMB6 {Hex(cpuId)} ({Smb6Means(reply.Smb6)}), {expected.Name} has {Hex(expected.CpuIdCode)}");
        }

        if (GeneratedFor(reply) != expected.Model)
        {
            var name = GeneratedFor(reply) is { } m ? CpuModelNames.Format(m) : "an unknown CPU";
            problems.Add($"the handler was generated for {name}, not {expected.Name}: regenerate it");
        }

        return problems.Count == 0 ? null : string.Join("; ", problems);
    }

    private static string Hex(byte value) => "16#" + value.ToString("X2", System.Globalization.CultureInfo.InvariantCulture);
}
