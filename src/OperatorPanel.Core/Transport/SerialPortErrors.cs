namespace OperatorPanel.Core.Transport;

/// <summary>
/// Turns what the serial library throws into the link's exception family: kind PortUnavailable, the port named, the
/// OS error named (errno on Linux/macOS, Win32 error on Windows) and what it means for a technician.
/// </summary>
internal static class SerialPortErrors
{
    private const string DeviceVanished = "the device vanished (unplugged?)";

    /// <summary>errno values shared by Linux and macOS for the failures a serial port really shows.</summary>
    private static readonly Dictionary<int, string> UnixNames = new()
    {
        [1] = "EPERM",
        [2] = "ENOENT",
        [5] = "EIO",
        [6] = "ENXIO",
        [13] = "EACCES",
        [16] = "EBUSY",
        [19] = "ENODEV",
        [21] = "EISDIR",
        [25] = "ENOTTY",
    };

    private static readonly Dictionary<string, string> UnixHints = new()
    {
        ["ENOENT"] = "no such port",
        ["EACCES"] = "access denied (on Linux the user must be in the dialout group)",
        ["EPERM"] = "access denied (on Linux the user must be in the dialout group)",
        ["EBUSY"] = "the port is in use by another program",
        ["ENOTTY"] = "not a serial device",
        ["EIO"] = DeviceVanished,
        ["ENXIO"] = DeviceVanished,
        ["ENODEV"] = DeviceVanished,
    };

    /// <summary>
    /// Win32 errors a COM port shows: 2/3 the name is unknown, 5 another program holds the port (COM ports open
    /// exclusively), 31/1167 the USB adapter was pulled.
    /// </summary>
    private static readonly Dictionary<int, string> WindowsHints = new()
    {
        [2] = "no such port",
        [3] = "no such port",
        [5] = "the port is in use by another program (or access denied)",
        [31] = DeviceVanished,
        [1167] = DeviceVanished,
    };

    /// <summary>Windows' access denial of a COM port, which in practice is another program holding it.</summary>
    public const string InUseOnWindows =
        "in use by another program: Windows lets one program at a time open a COM port (close Micro/WIN, a terminal program or another panel on it)";

    /// <summary>What opening the port may throw besides our own exceptions.</summary>
    public static bool IsOpenFailure(Exception exception) =>
        exception is IOException or UnauthorizedAccessException or ArgumentException or InvalidOperationException;

    /// <summary>
    /// What a read, write or discard may throw once the device is gone: an OS error, or the library's own "port is
    /// closed" when its I/O loop stopped on a hang-up (our own close is noticed before the call is made).
    /// </summary>
    public static bool IsDeviceFailure(Exception exception) =>
        exception is IOException or UnauthorizedAccessException or InvalidOperationException;

    public static PlcCommunicationException OpenFailed(string portName, Exception failure) => failure switch
    {
        ArgumentException => Unavailable(portName, $"the port name or its settings were refused: {failure.Message}"),

        // Unix reports every failed open as access denied, with the real errno in the inner exception.
        UnauthorizedAccessException { InnerException: IOException inner } => Unavailable(portName, "open failed: " + Describe(inner)),

        // Windows opens a COM port for one program at a time and says only "Access to the port 'COM3' is denied."
        UnauthorizedAccessException when OperatingSystem.IsWindows() => Unavailable(portName, InUseOnWindows),
        _ => Unavailable(portName, "open failed: " + Describe(failure)),
    };

    public static PlcCommunicationException Vanished(string portName, string action, Exception failure) =>
        Unavailable(portName, failure is IOException io ? $"{action} failed: {Describe(io)}" : $"{action} failed: {DeviceVanished}");

    public static PlcCommunicationException Unavailable(string portName, string detail) =>
        new(PlcErrorKind.PortUnavailable, null, $"serial port {portName}: {detail}");

    /// <summary>
    /// "No such file or directory (ENOENT) - no such port". On Unix the library puts the errno into HResult; on
    /// Windows HResult carries the Win32 error in its low word.
    /// </summary>
    private static string Describe(Exception failure)
    {
        if (OperatingSystem.IsWindows())
        {
            var win32 = failure.HResult & 0xFFFF;
            return WindowsHints.TryGetValue(win32, out var windowsHint)
                ? $"{failure.Message} (Win32 error {win32}) - {windowsHint}"
                : $"{failure.Message} (Win32 error {win32})";
        }

        if (failure.HResult is <= 0 or > 4095)
        {
            return failure.Message;
        }

        var name = UnixNames.GetValueOrDefault(failure.HResult, "errno " + failure.HResult);
        return UnixHints.TryGetValue(name, out var hint) ? $"{failure.Message} ({name}) - {hint}" : $"{failure.Message} ({name})";
    }
}
