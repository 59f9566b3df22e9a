using System.Diagnostics.CodeAnalysis;
using System.Text;
using OperatorPanel.Core.Messages;

namespace OperatorPanel.Core.Alarms;

/// <summary>
/// The alarm history of one project, kept beside the project file as JSON Lines (<c>line.opproj</c> →
/// <c>line.alarms.jsonl</c>). Each entry is appended with one write and flushed to disk, so a crash or power cut loses at
/// most the line being written; loading drops such a torn last line. A file that is corrupt anywhere else is renamed
/// aside (never deleted, never a crash) and a new history starts.
/// </summary>
public sealed class AlarmHistoryFile
{
    public const string Suffix = ".alarms.jsonl";

    private static readonly UTF8Encoding StrictUtf8 = new(encoderShouldEmitUTF8Identifier: false, throwOnInvalidBytes: true);
    private readonly TimeProvider _time;

    public AlarmHistoryFile(string path, TimeProvider time)
    {
        ArgumentException.ThrowIfNullOrWhiteSpace(path);
        ArgumentNullException.ThrowIfNull(time);
        Path = path;
        _time = time;
    }

    public string Path { get; }

    /// <summary>The history path for a project file: same folder, same name, <see cref="Suffix"/> instead of the extension.</summary>
    public static string PathFor(string projectPath) => System.IO.Path.ChangeExtension(projectPath, null) + Suffix;

    public AlarmHistoryLoad Load()
    {
        byte[] bytes;
        try
        {
            if (!File.Exists(Path))
            {
                return new AlarmHistoryLoad([], null);
            }

            bytes = File.ReadAllBytes(Path);
        }
        catch (Exception ex) when (IsEnvironmental(ex))
        {
            return new AlarmHistoryLoad([], $"The alarm history {Path} could not be read ({FileProblemText.Describe(ex, Path, FileAction.Read)}); new alarms are still recorded.");
        }

        var end = Array.LastIndexOf(bytes, (byte)'\n') + 1;
        var events = new List<AlarmEvent>();
        string text;
        try
        {
            text = StrictUtf8.GetString(bytes, 0, end);
        }
        catch (DecoderFallbackException)
        {
            return SetAside("it is not UTF-8 text");
        }

        var lines = text.Split('\n');
        for (var i = 0; i < lines.Length - 1; i++)
        {
            if (lines[i].Trim().Length == 0)
            {
                continue;
            }

            if (!AlarmHistoryLine.TryParse(lines[i], out var entry, out var error))
            {
                return SetAside(AlarmHistoryLine.Describe(i + 1, error));
            }

            events.Add(entry);
        }

        return end == bytes.Length ? new AlarmHistoryLoad([.. events], null) : DropTornTail(events, end);
    }

    /// <summary>Appends <paramref name="entries"/>, one write per line, then flushes to disk.</summary>
    public bool TryAppend(IReadOnlyList<AlarmEvent> entries, [NotNullWhen(false)] out string? error)
    {
        ArgumentNullException.ThrowIfNull(entries);
        error = null;
        if (entries.Count == 0)
        {
            return true;
        }

        try
        {
            using var stream = new FileStream(Path, FileMode.Append, FileAccess.Write, FileShare.Read);
            foreach (var entry in entries)
            {
                stream.Write(Encoding.UTF8.GetBytes(AlarmHistoryLine.Format(entry) + "\n"));
            }

            stream.Flush(flushToDisk: true);
            return true;
        }
        catch (Exception ex) when (IsEnvironmental(ex))
        {
            error = $"The alarm history {Path} could not be written: {FileProblemText.Describe(ex, Path, FileAction.Write)}";
            return false;
        }
    }

    /// <summary>An unterminated last line is a write the program did not finish: cut it off so the next append starts clean.</summary>
    private AlarmHistoryLoad DropTornTail(List<AlarmEvent> events, int end)
    {
        try
        {
            using var stream = new FileStream(Path, FileMode.Open, FileAccess.Write, FileShare.Read);
            stream.SetLength(end);
        }
        catch (Exception ex) when (IsEnvironmental(ex))
        {
            return SetAside($"its unfinished last line could not be removed ({FileProblemText.Describe(ex, Path, FileAction.Write)})");
        }

        return new AlarmHistoryLoad([.. events], $"The last alarm history entry in {Path} was cut short (the program stopped while writing it) and was dropped.");
    }

    private AlarmHistoryLoad SetAside(string why)
    {
        var aside = $"{Path}.corrupt-{_time.GetUtcNow().UtcDateTime:yyyyMMdd'T'HHmmss'Z'}";
        try
        {
            File.Move(Path, aside, overwrite: false);
        }
        catch (Exception ex) when (IsEnvironmental(ex))
        {
            return new AlarmHistoryLoad([], $"The alarm history {Path} is corrupt ({why}) and could not be set aside ({FileProblemText.Describe(ex, Path, FileAction.Write)}); move it away to record alarms again.");
        }

        return new AlarmHistoryLoad([], $"The alarm history {Path} is corrupt ({why}); it was kept as {aside} and a new history was started.");
    }

    private static bool IsEnvironmental(Exception ex) =>
        ex is IOException or UnauthorizedAccessException or NotSupportedException or System.Security.SecurityException;
}
