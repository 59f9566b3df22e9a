using System.CommandLine;
using System.Diagnostics.CodeAnalysis;
using OperatorPanel.Core.Cpu;

namespace OperatorPanel.Cli.Commands;

/// <summary>The --cpu and --revision options shared by verbs that need a CPU.</summary>
internal static class CpuOptions
{
    public static Option<string> Model(bool required = true) => new("--cpu")
    {
        Description = "CPU model: 221, 222, 224, 224XP or 226",
        Required = required,
    };

    public static Option<string?> Revision() => new("--revision")
    {
        Description = "CPU revision: Current (default) or Early (first generation, older manual)",
    };

    public static bool TryResolve(string? model, string? revision, [NotNullWhen(true)] out CpuProfile? profile, [NotNullWhen(false)] out string? error)
    {
        profile = null;
        if (!CpuModelNames.TryParse(model, out var cpuModel, out error))
        {
            return false;
        }

        var cpuRevision = CpuRevision.Current;
        if (revision is not null && !CpuModelNames.TryParseRevision(revision, out cpuRevision, out error))
        {
            return false;
        }

        if (!CpuProfiles.TryFor(cpuModel, cpuRevision, out var found))
        {
            error = $"{CpuModelNames.Format(cpuModel)} has no {cpuRevision} revision; it exists as: {string.Join(", ", CpuProfiles.RevisionsOf(cpuModel))}";
            return false;
        }

        profile = found;
        error = null;
        return true;
    }
}
