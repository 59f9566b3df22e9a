using System.Diagnostics.CodeAnalysis;
using System.Globalization;
using OperatorPanel.Core.Messages;

namespace OperatorPanel.Core.Projects;

/// <summary>
/// File access for project files (and the panel's other saved files: layout, alarm history, generated code) with the environment's failures (missing folder, access denied, disk full, a file
/// locked by another program) turned into messages. Writing never leaves a half-written target: the bytes go to a
/// temporary file in the same folder (same volume, so the final step is a rename) and replace the target at once;
/// the previous content becomes TARGET.bak the same way, so after a crash at any point the target and the .bak are
/// each a complete version.
/// </summary>
public static class AtomicFile
{
    private static readonly TimeSpan LeftoverAge = TimeSpan.FromMinutes(1);

    public static bool TryReadAll(string path, long maxBytes, [NotNullWhen(true)] out byte[]? bytes, [NotNullWhen(false)] out string? error)
    {
        bytes = null;
        try
        {
            // Read at most one byte past the limit instead of trusting the reported length: a device or pipe
            // (/dev/zero) reports 0 and never ends.
            using var stream = new FileStream(path, FileMode.Open, FileAccess.Read, FileShare.Read);
            using var buffer = new MemoryStream();
            var chunk = new byte[81920];
            int read;
            while ((read = stream.Read(chunk, 0, chunk.Length)) > 0)
            {
                buffer.Write(chunk, 0, read);
                if (buffer.Length > maxBytes)
                {
                    error = string.Create(CultureInfo.InvariantCulture, $"the file is larger than {maxBytes} bytes, the most this kind of file may have");
                    return false;
                }
            }

            bytes = buffer.ToArray();
            error = null;
            return true;
        }
        catch (Exception ex) when (IsEnvironmental(ex))
        {
            error = "cannot read it: " + FileProblemText.Describe(ex, path, FileAction.Read);
            return false;
        }
    }

    /// <summary>
    /// Writes <paramref name="content"/> to <paramref name="path"/> atomically, keeping an existing file's previous
    /// content as <c>path.bak</c>. Everything that would stop the replacement is checked before the .bak is touched (a
    /// read-only target or folder, a target that cannot be opened for writing: immutable, locked, not ours), so a refused
    /// save leaves the target and its .bak as they were. The new file keeps the old one's permissions (on Linux its
    /// mode: a project kept 0600 stays private).
    /// </summary>
    public static bool TryWrite(string path, byte[] content, [NotNullWhen(false)] out string? error)
    {
        string? temporary = null;
        string? backupCopy = null;
        var target = path;
        try
        {
            target = Path.GetFullPath(path);
            var folder = Path.GetDirectoryName(target) ?? ".";
            error = ReplaceProblem(folder, target);
            if (error is not null)
            {
                return false;
            }

            // The temporary file is also the test that the folder takes a new file (and so the final rename).
            temporary = WriteTemporary(folder, target, content);
            RemoveLeftovers(folder, target, temporary);

            if (File.Exists(target))
            {
                KeepMode(target, temporary);

                // The .bak is made from a complete copy and renamed into place, so at every instant it is a whole
                // earlier version (File.Replace on Linux unlinks the old .bak before linking the new one).
                backupCopy = WriteTemporary(folder, target, File.ReadAllBytes(target));
                KeepMode(target, backupCopy);
                File.Move(backupCopy, target + ".bak", overwrite: true);
                backupCopy = null;
            }

            File.Move(temporary, target, overwrite: true);
            temporary = null;
            error = null;
            return true;
        }
        catch (Exception ex) when (IsEnvironmental(ex))
        {
            error = "cannot save the file: " + WithoutTemporaryNames(FileProblemText.Describe(ex, target, FileAction.Write), target, temporary, backupCopy);
            return false;
        }
        finally
        {
            foreach (var leftover in new[] { temporary, backupCopy })
            {
                if (leftover is not null)
                {
                    TryDelete(leftover);
                }
            }
        }
    }

    /// <summary>
    /// Why <paramref name="target"/> cannot be replaced, found before anything is written; null when it can. Read-only is
    /// judged by the permissions (FileAttributes.ReadOnly: on Linux the write bit that applies to the user), not by
    /// trying: root may write a file or folder marked read-only, and a user who marked it so meant it to stay.
    /// </summary>
    private static string? ReplaceProblem(string folder, string target)
    {
        if (!Directory.Exists(folder))
        {
            // Said in our words: the exception would name the hidden temporary file, not the folder.
            return $"cannot save the file: the folder {folder} does not exist";
        }

        if (Directory.Exists(target))
        {
            return $"cannot save the file: {target} is a folder";
        }

        // Windows ignores a folder's Read-only attribute for what is inside (Explorer uses it to mark customised
        // folders), so only Linux and macOS folders are judged by it.
        if (!OperatingSystem.IsWindows() && File.GetAttributes(folder).HasFlag(FileAttributes.ReadOnly))
        {
            return $"cannot save the file: the folder {folder} is read-only: nothing written; make it writable (chmod u+w), or save elsewhere";
        }

        if (!File.Exists(target))
        {
            return null;
        }

        if (File.GetAttributes(target).HasFlag(FileAttributes.ReadOnly))
        {
            return $"cannot save the file: {target} is read-only: nothing written; make it writable to replace it "
                + "(chmod u+w on Linux, clear Read-only in its Properties on Windows), or save elsewhere";
        }

        try
        {
            // Opened for writing and closed at once, nothing written: an immutable file (chattr +i), one another
            // program holds locked, or one of another user fails here, before the .bak is renewed.
            using var probe = new FileStream(target, FileMode.Open, FileAccess.Write, FileShare.ReadWrite | FileShare.Delete);
            return null;
        }
        catch (UnauthorizedAccessException)
        {
            // EACCES and EPERM alike: its permissions or ACL, or (root included) Linux's immutable or append-only attribute.
            return "cannot save the file: the system refuses to open it for writing (its permissions, or on Linux an immutable "
                + "or append-only attribute: lsattr shows i or a): nothing written";
        }
        catch (Exception ex) when (IsEnvironmental(ex))
        {
            return $"cannot save the file: {FileProblemText.Describe(ex, target, FileAction.Write)}: nothing written";
        }
    }

    /// <summary>The new version keeps the old one's Linux mode (a temporary file gets 0666 less the umask).</summary>
    private static void KeepMode(string target, string copy)
    {
        if (!OperatingSystem.IsWindows())
        {
            File.SetUnixFileMode(copy, File.GetUnixFileMode(target));
        }
    }

    /// <summary>The system's message with our hidden temporary files named as the file the user asked to save.</summary>
    private static string WithoutTemporaryNames(string message, string target, params string?[] temporaries)
    {
        foreach (var temporary in temporaries)
        {
            if (temporary is not null)
            {
                message = message.Replace(temporary, target, StringComparison.Ordinal);
            }
        }

        return message;
    }

    /// <summary>A hidden file beside the target (same volume, so the final step is a rename), flushed to the disk.</summary>
    private static string WriteTemporary(string folder, string target, byte[] content)
    {
        var temporary = Path.Combine(folder, $"{TemporaryPrefix(target)}{Guid.NewGuid():N}.tmp");
        using var stream = new FileStream(temporary, FileMode.CreateNew, FileAccess.Write, FileShare.None);
        stream.Write(content);
        stream.Flush(flushToDisk: true);
        return temporary;
    }

    private static string TemporaryPrefix(string target) => $".{Path.GetFileName(target)}.";

    /// <summary>
    /// Temporary files of this target left by a save that was killed. Only those a minute older than our own fresh
    /// one go (timestamps of one file system, so no clock of ours is involved): a save running now in another
    /// process keeps its file.
    /// </summary>
    private static void RemoveLeftovers(string folder, string target, string ours)
    {
        var cutoff = File.GetLastWriteTimeUtc(ours) - LeftoverAge;
        foreach (var candidate in Directory.EnumerateFiles(folder, TemporaryPrefix(target) + "*.tmp"))
        {
            if (candidate != ours && File.GetLastWriteTimeUtc(candidate) < cutoff)
            {
                TryDelete(candidate);
            }
        }
    }

    private static bool IsEnvironmental(Exception ex) =>
        ex is IOException or UnauthorizedAccessException or NotSupportedException or ArgumentException or System.Security.SecurityException;

    /// <summary>Best effort: a leftover hidden .tmp file beside the project is harmless; the next save removes it.</summary>
    private static void TryDelete(string path)
    {
        try
        {
            File.Delete(path);
        }
        catch (Exception ex) when (IsEnvironmental(ex))
        {
            System.Diagnostics.Debug.WriteLine($"could not remove {path}: {ex.Message}");
        }
    }
}
