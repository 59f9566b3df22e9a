namespace OperatorPanel.Core.Messages;

/// <summary>
/// A file that could not be read or written, said in our words in one clause ("it is a folder, not a file", "the folder
/// C:\Lines does not exist"), never the runtime's ("Access to the path '...' is denied."). The caller names the file.
/// The codes are the OS's own: on Windows HResult carries the Win32 error in its low word (32 sharing violation, 33 lock
/// violation, 112 disk full); on Linux the runtime puts the errno into HResult (28 ENOSPC, 30 EROFS, 11 EAGAIN from a
/// lock another process holds).
/// </summary>
public static class FileProblemText
{
    public static string Describe(Exception failure, string path, FileAction action)
    {
        ArgumentNullException.ThrowIfNull(failure);
        var verb = action == FileAction.Read ? "read" : "write";
        if (!string.IsNullOrEmpty(path) && Directory.Exists(path))
        {
            return "it is a folder, not a file";
        }

        return failure switch
        {
            FileNotFoundException => "there is no such file",
            DirectoryNotFoundException => FolderOf(path) is { } folder ? $"the folder {folder} does not exist" : "its folder does not exist",
            PathTooLongException => "the path is too long for the system",
            UnauthorizedAccessException => $"access denied: the user running the panel may not {verb} it",
            ArgumentException or NotSupportedException => "the name is not a valid file path",
            IOException io when IsLocked(io) => "another program has it open and locked; close that program and try again",
            IOException io when IsDiskFull(io) => "the disk is full",
            IOException io when IsReadOnlyDisk(io) => "the disk or share is read-only",
            _ => $"the system could not {verb} it ({failure.Message.TrimEnd('.')})",
        };
    }

    /// <summary>The first folder of <paramref name="path"/> that is missing, so the message points at what to create.</summary>
    private static string? FolderOf(string path)
    {
        try
        {
            var folder = Path.GetDirectoryName(Path.GetFullPath(path));
            while (folder is not null && Path.GetDirectoryName(folder) is { } parent && !Directory.Exists(parent))
            {
                folder = parent;
            }

            return folder;
        }
        catch (Exception ex) when (ex is ArgumentException or NotSupportedException or PathTooLongException or System.Security.SecurityException)
        {
            return null;
        }
    }

    private static bool IsLocked(IOException io) => Win32(io) is 32 or 33 || (!OperatingSystem.IsWindows() && io.HResult == 11);

    private static bool IsDiskFull(IOException io) => Win32(io) is 39 or 112 || (!OperatingSystem.IsWindows() && io.HResult == 28);

    private static bool IsReadOnlyDisk(IOException io) => Win32(io) is 19 || (!OperatingSystem.IsWindows() && io.HResult == 30);

    /// <summary>The Win32 error of an HRESULT of facility Win32 (0x8007xxxx); null otherwise.</summary>
    private static int? Win32(IOException io) => (io.HResult & 0xFFFF0000) == 0x80070000 ? io.HResult & 0xFFFF : null;
}
