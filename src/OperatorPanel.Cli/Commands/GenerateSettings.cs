using System.Diagnostics.CodeAnalysis;
using System.Globalization;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Projects;
using OperatorPanel.StlGen.Options;

namespace OperatorPanel.Cli.Commands;

/// <summary>
/// The command-line side of <c>opanel generate</c>: picks the station and turns the option texts into
/// <see cref="HandlerOptions"/>. Unreadable text (not a V byte, an unknown area letter) is bad input here; readable but
/// impossible values (VB9000 on a CPU 224) pass through so the generator reports them with their STL IDs.
/// </summary>
internal static class GenerateSettings
{
    public static bool TrySelectStation(PanelProject project, string? wanted, [NotNullWhen(true)] out ProjectStation? station, [NotNullWhen(false)] out string? error)
    {
        station = null;
        if (wanted is null)
        {
            if (project.Stations.Length == 1)
            {
                station = project.Stations[0];
                error = null;
                return true;
            }

            error = $"the project has {project.Stations.Length} stations ({Names(project)}); choose one with --station NAME|ADDRESS";
            return false;
        }

        var byAddress = int.TryParse(wanted, NumberStyles.None, CultureInfo.InvariantCulture, out var address);
        station = project.Stations.FirstOrDefault(s => string.Equals(s.Name, wanted, StringComparison.OrdinalIgnoreCase) || (byAddress && s.Address.Address == address));
        error = station is null ? $"no station '{wanted}' in the project; stations: {Names(project)}" : null;
        return station is not null;
    }

    /// <summary>"VB1000" -> 1000.</summary>
    public static bool TryParseBuffer(string text, out int start, [NotNullWhen(false)] out string? error)
    {
        start = 0;
        if (!PlcAddress.TryParse(text, out var address, out var parseError))
        {
            error = $"--buffer {text}: {parseError.Message}";
            return false;
        }

        if (address.Area != MemoryArea.V || address.Width != AccessWidth.Byte)
        {
            error = $"--buffer {text}: give the handler's first V byte, e.g. VB1000";
            return false;
        }

        start = address.ByteOffset;
        error = null;
        return true;
    }

    /// <summary>"Q,M,V,SM" -> the protocol write mask (bit n = area code n). I is kept so the generator can refuse it (STL011).</summary>
    public static bool TryParseWritable(string text, out int mask, [NotNullWhen(false)] out string? error)
    {
        mask = 0;
        foreach (var part in text.Split(',', StringSplitOptions.TrimEntries | StringSplitOptions.RemoveEmptyEntries))
        {
            var code = part.ToUpperInvariant() switch { "I" => 1, "Q" => 2, "M" => 3, "V" => 4, "SM" => 5, _ => 0 };
            if (code == 0)
            {
                error = $"--writable: '{part}' is not an area; use a comma-separated list of Q, M, V, SM";
                return false;
            }

            mask |= 1 << code;
        }

        error = null;
        return true;
    }

    private static string Names(PanelProject project) =>
        string.Join(", ", project.Stations.Select(s => $"{s.Name} ({s.Address.Address.ToString(CultureInfo.InvariantCulture)})"));
}
