using System.Diagnostics;
using System.Text;

namespace OperatorPanel.Core.Transport;

/// <summary>
/// Another process as a technician recognises it: "opanel watch line.opproj", "minicom", "OperatorPanel". On Linux the
/// command line comes from /proc/PID/cmdline (NUL-separated), with "dotnet" in front of an assembly dropped; elsewhere
/// the process name.
/// </summary>
internal static class ProcessText
{
    private const int MaxChars = 80;

    /// <summary>The running process <paramref name="pid"/> in words; null when no such process runs.</summary>
    public static string? DescribeRunning(int pid)
    {
        string name;
        try
        {
            using var process = Process.GetProcessById(pid);
            if (process.HasExited)
            {
                return null;
            }

            name = process.ProcessName;
        }
        catch (Exception ex) when (ex is ArgumentException or InvalidOperationException or System.ComponentModel.Win32Exception or NotSupportedException)
        {
            return null;
        }

        return OperatingSystem.IsLinux() && CommandLine(pid) is { Length: > 0 } line ? line : name;
    }

    private static string? CommandLine(int pid)
    {
        string[] words;
        try
        {
            words = File.ReadAllText($"/proc/{pid}/cmdline", Encoding.UTF8).Split('\0', StringSplitOptions.RemoveEmptyEntries);
        }
        catch (Exception ex) when (ex is IOException or UnauthorizedAccessException)
        {
            return null;
        }

        if (words.Length > 1 && Path.GetFileNameWithoutExtension(words[0]) == "dotnet" && words[1].EndsWith(".dll", StringComparison.OrdinalIgnoreCase))
        {
            words = [Path.GetFileNameWithoutExtension(words[1]), .. words[2..]];
        }
        else if (words.Length > 0)
        {
            words[0] = Path.GetFileName(words[0]);
        }

        var text = string.Join(' ', words);
        return text.Length <= MaxChars ? text : text[..(MaxChars - 3)] + "...";
    }
}
