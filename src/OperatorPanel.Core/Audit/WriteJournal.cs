using System.Diagnostics;
using System.Text;
using OperatorPanel.Core.Messages;

namespace OperatorPanel.Core.Audit;

/// <summary>
/// The write journal: every write and STOP on record before its frame leaves, and its outcome after, in one JSON Lines
/// file per user shared by the app and opanel (beside the logs). Each entry is appended whole under an exclusive open
/// (other programs appending wait their turn) and flushed to the disk before <see cref="RecordAsync"/> returns, so a
/// kill or a power cut after it cannot lose it. An intent without outcome whose program has ended was cut short: a
/// later start finds it (<see cref="CutShort"/>) and settles it by reading the target back (Writes/UnfinishedWrites).
/// A journal over <see cref="RotateBytes"/> with nothing unsettled is renamed aside (kept) and a new one begun.
/// </summary>
public sealed class WriteJournal : IAuditTrail
{
    public const string FileName = "write-journal.jsonl";

    /// <summary>About 8,000 writes; the journal is read whole at every start.</summary>
    public const long RotateBytes = 4 * 1024 * 1024;

    /// <summary>How long an append waits for another program's append before it gives up.</summary>
    private static readonly TimeSpan BusyLimit = TimeSpan.FromSeconds(2);

    private static readonly TimeSpan BusyRetry = TimeSpan.FromMilliseconds(20);
    private static readonly Lazy<DateTimeOffset> OurStart = new(() => Process.GetCurrentProcess().StartTime.ToUniversalTime());
    private readonly TimeProvider _time;

    public WriteJournal(string path, TimeProvider? time = null)
    {
        ArgumentException.ThrowIfNullOrWhiteSpace(path);
        Path = path;
        _time = time ?? TimeProvider.System;
    }

    public string Path { get; }

    /// <summary>The journal in <paramref name="folder"/> (the log folder of the app and opanel).</summary>
    public static WriteJournal In(string folder, TimeProvider? time = null) => new(System.IO.Path.Combine(folder, FileName), time);

    public async ValueTask<string?> RecordAsync(AuditEntry entry, CancellationToken cancellationToken)
    {
        ArgumentNullException.ThrowIfNull(entry);
        var bytes = Encoding.UTF8.GetBytes(new JournalLine(entry, Environment.ProcessId, OurStart.Value).Format() + "\n");
        var start = _time.GetTimestamp();
        while (true)
        {
            try
            {
                Append(bytes);
                return null;
            }
            catch (IOException busy) when (IsBusy(busy) && _time.GetElapsedTime(start) < BusyLimit)
            {
                // Another program (or another bus of ours) is appending: wait our turn. Not cancelled: an outcome must reach the record.
                await Task.Delay(BusyRetry, _time, CancellationToken.None).ConfigureAwait(false);
            }
            catch (Exception ex) when (ex is IOException or UnauthorizedAccessException or NotSupportedException or ArgumentException)
            {
                return $"the write journal {Path} could not be written: {FileProblemText.Describe(ex, Path, FileAction.Write)}";
            }
        }
    }

    /// <summary>
    /// Intents without outcome on ports <paramref name="onPort"/> accepts, whose program has ended (a program still
    /// running has them on the wire now), oldest first; and a message when the journal could not be read.
    /// </summary>
    public (IReadOnlyList<AuditEntry> Intents, string? Problem) CutShort(Func<string, bool> onPort)
    {
        ArgumentNullException.ThrowIfNull(onPort);
        var (lines, problem) = Read();
        var settled = lines.Where(l => l.Entry.Step != AuditStep.Intent).Select(l => l.Entry.Id).ToHashSet();
        var open = lines.Where(l => l.Entry.Step == AuditStep.Intent && !settled.Contains(l.Entry.Id)).ToList();
        if (open.Count == 0 && problem is null)
        {
            RotateIfLarge();
        }

        return ([.. open.Where(l => onPort(l.Entry.Port) && !IsRunning(l.Pid, l.ProcessStarted)).Select(l => l.Entry)], problem);
    }

    private void Append(byte[] bytes)
    {
        var folder = System.IO.Path.GetDirectoryName(System.IO.Path.GetFullPath(Path));
        if (folder is not null)
        {
            Directory.CreateDirectory(folder);
        }

        // FileShare.None: an exclusive open (flock on Linux), so appends of two programs never interleave.
        using var stream = new FileStream(Path, FileMode.OpenOrCreate, FileAccess.ReadWrite, FileShare.None);
        if (stream.Length > 0)
        {
            // A line torn by a kill ends without '\n': start on a line of our own, or this entry is lost with it.
            stream.Seek(-1, SeekOrigin.End);
            var last = stream.ReadByte();
            if (last != '\n')
            {
                stream.WriteByte((byte)'\n');
            }
        }

        stream.Seek(0, SeekOrigin.End);
        stream.Write(bytes);
        stream.Flush(flushToDisk: true);
    }

    private (List<JournalLine> Lines, string? Problem) Read()
    {
        string text;
        try
        {
            if (!File.Exists(Path))
            {
                return ([], null);
            }

            using var stream = new FileStream(Path, FileMode.Open, FileAccess.Read, FileShare.ReadWrite);
            using var reader = new StreamReader(stream, Encoding.UTF8);
            text = reader.ReadToEnd();
        }
        catch (Exception ex) when (ex is IOException or UnauthorizedAccessException or NotSupportedException or ArgumentException)
        {
            return ([], $"the write journal {Path} could not be read: {FileProblemText.Describe(ex, Path, FileAction.Read)}; writes cut short earlier are not settled");
        }

        var lines = new List<JournalLine>();
        var torn = 0;
        foreach (var raw in text.Split('\n', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries))
        {
            if (JournalLine.TryParse(raw, out var line))
            {
                lines.Add(line);
            }
            else
            {
                torn++;
            }
        }

        return (lines, torn == 0 ? null : $"the write journal {Path} has {torn} line(s) that are not entries (torn by a kill, or edited); they were skipped");
    }

    private void RotateIfLarge()
    {
        try
        {
            if (File.Exists(Path) && new FileInfo(Path).Length > RotateBytes)
            {
                var stamp = _time.GetUtcNow().UtcDateTime.ToString("yyyyMMdd'T'HHmmss'Z'", System.Globalization.CultureInfo.InvariantCulture);
                File.Move(Path, System.IO.Path.ChangeExtension(Path, null) + "-" + stamp + ".jsonl", overwrite: false);
            }
        }
        catch (Exception ex) when (ex is IOException or UnauthorizedAccessException)
        {
            Debug.WriteLine($"write journal {Path} not rotated: {ex.Message}");
        }
    }

    /// <summary>
    /// Another program holds the journal open: a sharing or lock violation on Windows (Win32 32, 33), a held flock on
    /// Linux (EWOULDBLOCK, errno 11) or macOS (35).
    /// </summary>
    private static bool IsBusy(IOException ex) => ex.HResult is unchecked((int)0x80070020) or unchecked((int)0x80070021)
        || (OperatingSystem.IsLinux() && ex.HResult == 11) || (OperatingSystem.IsMacOS() && ex.HResult == 35);

    /// <summary>True when <paramref name="pid"/> is still the process that wrote the entry (same start time; PIDs are reused).</summary>
    private static bool IsRunning(int pid, DateTimeOffset started)
    {
        try
        {
            using var process = Process.GetProcessById(pid);
            return !process.HasExited && (process.StartTime.ToUniversalTime() - started.UtcDateTime).Duration() < TimeSpan.FromSeconds(2);
        }
        catch (ArgumentException)
        {
            return false; // no such process
        }
        catch (Exception ex) when (ex is InvalidOperationException or System.ComponentModel.Win32Exception or NotSupportedException)
        {
            return true; // cannot tell: leave it to its program rather than settle a write that may be on the wire now
        }
    }
}
