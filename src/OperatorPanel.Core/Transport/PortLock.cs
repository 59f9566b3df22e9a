using System.Diagnostics;
using System.Diagnostics.CodeAnalysis;
using System.Globalization;
using System.Text;

namespace OperatorPanel.Core.Transport;

/// <summary>
/// One program per serial port. Two programs on one RS-485 line garble each other's frames, and the technician is then
/// sent to check wiring and line settings. Windows opens a COM port for one program at a time by itself. Linux does not:
/// its exclusive mode (the TIOCEXCL ioctl) is out of reach of the .NET serial library without P/Invoke, which this product
/// does not use, so the port is claimed by a lock file in the UUCP convention that Linux serial programs share
/// (Filesystem Hierarchy Standard 3.0, section 5.9 "/var/lock": "LCK.." and the device's base name, holding the
/// owner's PID as ten ASCII digits, space-padded, and a newline). A lock whose process is gone is stale and taken
/// over, so a killed panel never blocks the port. Programs that ignore the convention are not stopped by it; the
/// message then cannot name them. On Windows the same file (under the user's application data) lets the message name
/// another panel holding the port.
/// </summary>
public sealed class PortLock : IDisposable
{
    private static readonly Lock HeldLock = new();
    private static readonly HashSet<string> Held = new(StringComparer.Ordinal);
    private readonly string _path;
    private int _released;

    private PortLock(string path) => _path = path;

    /// <summary>Where lock files go: /var/lock on Linux (shared with other serial programs), else the user's application data.</summary>
    public static string DefaultFolder { get; } = !OperatingSystem.IsWindows() && Directory.Exists("/var/lock")
        ? "/var/lock"
        : Path.Combine(Environment.GetFolderPath(Environment.SpecialFolder.LocalApplicationData, Environment.SpecialFolderOption.Create), "OperatorPanel", "locks");

    /// <summary>The lock file of <paramref name="portName"/> in <paramref name="folder"/>: LCK..ttyUSB0, LCK..pts_4, LCK..COM3.</summary>
    public static string PathFor(string portName, string folder) => Path.Combine(folder, "LCK.." + DeviceName(portName));

    /// <summary>
    /// Claims <paramref name="portName"/> for this process; false with a sentence naming the port and, when known, the
    /// program holding it. A folder that cannot take lock files (none, read-only) claims nothing and refuses nothing:
    /// the port's own open decides then.
    /// </summary>
    public static bool TryAcquire(string portName, string folder, out PortLock? held, [NotNullWhen(false)] out string? error)
    {
        ArgumentException.ThrowIfNullOrWhiteSpace(portName);
        var path = PathFor(portName, folder);
        held = null;
        error = null;
        TryCreateFolder(folder);
        lock (HeldLock)
        {
            if (Held.Contains(path))
            {
                error = $"serial port {portName} is already open in this program";
                return false;
            }

            for (var attempt = 0; attempt < 2; attempt++)
            {
                if (TryCreate(path))
                {
                    Held.Add(path);
                    held = new PortLock(path);
                    return true;
                }

                if (!File.Exists(path))
                {
                    return true; // the folder takes no lock files: nothing claimed, nothing refused
                }

                if (ReadOwner(path) is { } owner && owner != Environment.ProcessId && ProcessText.DescribeRunning(owner) is { } program)
                {
                    error = $"serial port {portName} is in use by another program: {program} (PID {owner}); close it first, one program per port";
                    return false;
                }

                TryDelete(path); // stale: its process is gone (or it is an old lock of ours by PID reuse)
            }
        }

        return true;
    }

    public void Dispose()
    {
        if (Interlocked.Exchange(ref _released, 1) == 1)
        {
            return;
        }

        lock (HeldLock)
        {
            Held.Remove(_path);
            TryDelete(_path);
        }
    }

    /// <summary>Resolves links (/dev/serial/by-id/..., a socat link) to the device; /dev/pts/4 becomes pts_4.</summary>
    private static string DeviceName(string portName)
    {
        var device = portName;
        try
        {
            device = File.ResolveLinkTarget(portName, returnFinalTarget: true)?.FullName ?? portName;
        }
        catch (Exception ex) when (ex is IOException or UnauthorizedAccessException or ArgumentException)
        {
            // Not a link, or not a path (COM3): the name is the device.
        }

        var name = device.StartsWith("/dev/", StringComparison.Ordinal) ? device["/dev/".Length..] : Path.GetFileName(device);
        return new string([.. name.Select(c => char.IsAsciiLetterOrDigit(c) || c is '-' or '.' ? c : '_')]);
    }

    private static bool TryCreate(string path)
    {
        try
        {
            using var file = new FileStream(path, FileMode.CreateNew, FileAccess.Write, FileShare.Read);
            file.Write(Encoding.ASCII.GetBytes(Environment.ProcessId.ToString(CultureInfo.InvariantCulture).PadLeft(10) + "\n"));
            return true;
        }
        catch (Exception ex) when (ex is IOException or UnauthorizedAccessException)
        {
            return false;
        }
    }

    private static void TryCreateFolder(string folder)
    {
        try
        {
            Directory.CreateDirectory(folder);
        }
        catch (Exception ex) when (ex is IOException or UnauthorizedAccessException or ArgumentException or NotSupportedException)
        {
            Debug.WriteLine($"port lock folder {folder} not created: {ex.Message}");
        }
    }

    private static int? ReadOwner(string path)
    {
        try
        {
            var text = File.ReadAllText(path, Encoding.ASCII).Trim();
            return int.TryParse(text, NumberStyles.None, CultureInfo.InvariantCulture, out var pid) && pid > 0 ? pid : null;
        }
        catch (Exception ex) when (ex is IOException or UnauthorizedAccessException)
        {
            return null;
        }
    }

    private static void TryDelete(string path)
    {
        try
        {
            File.Delete(path);
        }
        catch (Exception ex) when (ex is IOException or UnauthorizedAccessException)
        {
            Debug.WriteLine($"port lock {path} not removed: {ex.Message}");
        }
    }
}
