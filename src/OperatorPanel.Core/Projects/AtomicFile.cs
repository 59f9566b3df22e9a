using System.Diagnostics.CodeAnalysis;
using System.Globalization;

namespace OperatorPanel.Core.Projects;

/// <summary>
/// File access for project files with the environment's failures (missing folder, access denied, disk full, a file
/// locked by another program) turned into messages. Writing never leaves a half-written target: the bytes go to a
/// temporary file in the same folder (same volume, so the final step is a rename) and replace the target at once.
/// </summary>
public static class AtomicFile
{
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
                    error = string.Create(CultureInfo.InvariantCulture, $"the file is larger than {maxBytes} bytes, the most a project file may have");
                    return false;
                }
            }

            bytes = buffer.ToArray();
            error = null;
            return true;
        }
        catch (Exception ex) when (IsEnvironmental(ex))
        {
            error = "cannot read the file: " + ex.Message;
            return false;
        }
    }

    public static bool TryWrite(string path, byte[] content, [NotNullWhen(false)] out string? error)
    {
        string? temporary = null;
        try
        {
            var target = Path.GetFullPath(path);
            temporary = Path.Combine(
                Path.GetDirectoryName(target) ?? ".",
                $".{Path.GetFileName(target)}.{Guid.NewGuid():N}.tmp");
            using (var stream = new FileStream(temporary, FileMode.CreateNew, FileAccess.Write, FileShare.None))
            {
                stream.Write(content);
                // Flush to the disk, not just the OS cache, before the rename makes the new content the file.
                stream.Flush(flushToDisk: true);
            }

            if (File.Exists(target))
            {
                File.Replace(temporary, target, target + ".bak", ignoreMetadataErrors: true);
            }
            else
            {
                File.Move(temporary, target);
            }

            temporary = null;
            error = null;
            return true;
        }
        catch (Exception ex) when (IsEnvironmental(ex))
        {
            error = "cannot save the file: " + ex.Message;
            return false;
        }
        finally
        {
            if (temporary is not null)
            {
                TryDelete(temporary);
            }
        }
    }

    private static bool IsEnvironmental(Exception ex) =>
        ex is IOException or UnauthorizedAccessException or NotSupportedException or ArgumentException or System.Security.SecurityException;

    /// <summary>Best effort: a leftover hidden .tmp file beside the project is harmless, and the save already failed.</summary>
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
