using System.Globalization;
using OperatorPanel.Core.Cpu;

namespace OperatorPanel.Core.Protocol;

/// <summary>
/// Reads an IDENTIFY reply against the CPU a project expects (docs/protocol-v2.md, "01 IDENTIFY"). CPU 224 and 224XP share
/// SMB6 16#20 (docs/cpu-profiles.md), so SMB6 is compared by code only; the handler's own CPU code names the exact model
/// it was generated for.
/// </summary>
public static class IdentifyCheck
{
    /// <summary>The model the handler was generated for; null for a code this program does not know.</summary>
    public static CpuModel? GeneratedFor(IdentifyResponse reply)
    {
        ArgumentNullException.ThrowIfNull(reply);
        return Enum.GetValues<CpuModel>().Where(m => HandlerIdentity.CpuModelCode(m) == reply.CpuModelCode).Select(m => (CpuModel?)m).FirstOrDefault();
    }

    /// <summary>"CPU 224 (early)" or "unknown CPU code 9".</summary>
    public static string DescribeGeneratedFor(IdentifyResponse reply)
    {
        ArgumentNullException.ThrowIfNull(reply);
        var revision = reply.CpuRevisionCode == HandlerIdentity.CpuRevisionCode(CpuRevision.Early) ? " (early)" : string.Empty;
        return GeneratedFor(reply) is { } model
            ? CpuModelNames.Format(model) + revision
            : string.Create(CultureInfo.InvariantCulture, $"unknown CPU code {reply.CpuModelCode}");
    }

    /// <summary>Null when the PLC and its handler match <paramref name="expected"/>; otherwise every difference, joined by "; ".</summary>
    public static string? Mismatch(IdentifyResponse reply, CpuProfile expected)
    {
        ArgumentNullException.ThrowIfNull(reply);
        ArgumentNullException.ThrowIfNull(expected);
        var problems = new List<string>();
        var cpuId = (byte)(reply.Smb6 & 0xF0);
        if (cpuId != expected.CpuIdCode)
        {
            var models = CpuProfiles.All.Where(p => p.CpuIdCode == cpuId).Select(p => p.Name).Distinct().ToList();
            var means = models.Count == 0 ? "an unknown CPU type" : string.Join(" or ", models);
            problems.Add($"the PLC reports SMB6 {Hex(cpuId)} ({means}), {expected.Name} has {Hex(expected.CpuIdCode)}");
        }

        if (GeneratedFor(reply) != expected.Model)
        {
            problems.Add($"the handler was generated for {DescribeGeneratedFor(reply)}, not {expected.Name}: regenerate it");
        }

        return problems.Count == 0 ? null : string.Join("; ", problems);
    }

    private static string Hex(byte value) => "16#" + value.ToString("X2", CultureInfo.InvariantCulture);
}
