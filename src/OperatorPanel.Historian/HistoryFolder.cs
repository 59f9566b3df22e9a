using System.Security.Cryptography;
using System.Text;

namespace OperatorPanel.Historian;

/// <summary>
/// Where the history databases live: one per project, beside the user's logs in the local application data folder
/// (<c>%LOCALAPPDATA%\OperatorPanel\history</c> on Windows, <c>~/.local/share/OperatorPanel/history</c> on Linux), never
/// beside the project file, which may sit on a read-only share or travel on a USB stick. A project's database is named
/// for its file and a hash of the file's full path, so two lines' projects of the same name never share history; the
/// demo line has its own, so simulated values never mix with a real line's.
/// </summary>
public sealed class HistoryFolder(string path)
{
    public const string Extension = ".history.db";

    /// <summary>The user's history folder: LocalApplicationData/OperatorPanel/history.</summary>
    public static HistoryFolder Default { get; } = new(System.IO.Path.Combine(
        Environment.GetFolderPath(Environment.SpecialFolder.LocalApplicationData, Environment.SpecialFolderOption.Create),
        "OperatorPanel",
        "history"));

    public string Path { get; } = System.IO.Path.GetFullPath(path ?? throw new ArgumentNullException(nameof(path)));

    /// <summary>"bottling-line-3f2a9c1e.history.db" (or "…-demo.history.db") for the project file at <paramref name="projectPath"/>.</summary>
    public string DatabaseFor(string projectPath, bool demo)
    {
        ArgumentException.ThrowIfNullOrWhiteSpace(projectPath);
        var full = System.IO.Path.GetFullPath(projectPath);
        // Windows paths ignore case: C:\Lines\A.opproj and c:\lines\a.opproj are one project.
        var key = OperatingSystem.IsWindows() ? full.ToUpperInvariant() : full;
        var hash = Convert.ToHexStringLower(SHA256.HashData(Encoding.UTF8.GetBytes(key)))[..8];
        var stem = Sanitize(System.IO.Path.GetFileNameWithoutExtension(full));
        return System.IO.Path.Combine(Path, $"{stem}-{hash}{(demo ? "-demo" : string.Empty)}{Extension}");
    }

    /// <summary>File-name characters only, at most 40 of them, so any project name gives a valid file name everywhere.</summary>
    private static string Sanitize(string stem)
    {
        var invalid = System.IO.Path.GetInvalidFileNameChars();
        var clean = new string([.. stem.Take(40).Select(c => invalid.Contains(c) || char.IsWhiteSpace(c) || c is '\\' or '/' or ':' or '*' or '?' or '"' or '<' or '>' or '|' ? '-' : char.ToLowerInvariant(c))]);
        return clean.Length == 0 ? "project" : clean;
    }
}
