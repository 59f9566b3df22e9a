using System.Diagnostics.CodeAnalysis;

namespace OperatorPanel.Core.Cpu;

/// <summary>Reads and prints CPU model names as technicians write them: "224", "CPU 224XP", "cpu226".</summary>
public static class CpuModelNames
{
    public static string Format(CpuModel model) => "CPU " + ShortName(model);

    /// <summary>The name without "CPU ", as used in file names and on the command line: "224XP".</summary>
    public static string ShortName(CpuModel model) => model switch
    {
        CpuModel.Cpu221 => "221",
        CpuModel.Cpu222 => "222",
        CpuModel.Cpu224 => "224",
        CpuModel.Cpu224XP => "224XP",
        CpuModel.Cpu226 => "226",
    };

    public static bool TryParse([NotNullWhen(true)] string? text, out CpuModel model, [NotNullWhen(false)] out string? error)
    {
        var compact = (text ?? string.Empty).Replace(" ", string.Empty, StringComparison.Ordinal).ToUpperInvariant();
        if (compact.StartsWith("CPU", StringComparison.Ordinal))
        {
            compact = compact[3..];
        }

        foreach (var candidate in Enum.GetValues<CpuModel>())
        {
            if (ShortName(candidate) == compact)
            {
                model = candidate;
                error = null;
                return true;
            }
        }

        model = default;
        error = $"unknown CPU '{text}'; supported: 221, 222, 224, 224XP, 226";
        return false;
    }

    public static bool TryParseRevision([NotNullWhen(true)] string? text, out CpuRevision revision, [NotNullWhen(false)] out string? error)
    {
        if (Enum.TryParse(text?.Trim(), ignoreCase: true, out revision) && Enum.IsDefined(revision))
        {
            error = null;
            return true;
        }

        error = $"unknown CPU revision '{text}'; use Current (default) or Early";
        return false;
    }
}
