using System.Runtime.InteropServices;

namespace OperatorPanel.Core.Transport.Serial;

/// <summary>Turns OS error codes of the serial devices into the link's exception family, naming port and error.</summary>
internal static class SerialPortErrors
{
    /// <summary>errno values shared by Linux and macOS for the failures a serial port really shows.</summary>
    private static readonly Dictionary<int, string> UnixNames = new()
    {
        [2] = "ENOENT",
        [5] = "EIO",
        [6] = "ENXIO",
        [13] = "EACCES",
        [16] = "EBUSY",
        [19] = "ENODEV",
        [25] = "ENOTTY",
    };

    /// <summary>The errors after which the device is gone (USB adapter unplugged, pty master closed).</summary>
    private static readonly HashSet<string> VanishedNames = ["EIO", "ENXIO", "ENODEV"];

    public static PlcCommunicationException Unix(string portName, string action, int errno)
    {
        var name = UnixNames.GetValueOrDefault(errno, "errno " + errno);
        var hint = VanishedNames.Contains(name) ? " - the device vanished (unplugged?)" : "";
        return Unavailable(portName, $"{action} failed: {Marshal.GetPInvokeErrorMessage(errno)} ({name}){hint}");
    }

    public static PlcCommunicationException Windows(string portName, string action, int win32Error) =>
        Unavailable(portName, $"{action} failed: {Marshal.GetPInvokeErrorMessage(win32Error)} (Win32 error {win32Error})");

    public static PlcCommunicationException Unavailable(string portName, string detail) =>
        new(PlcErrorKind.PortUnavailable, null, $"serial port {portName}: {detail}");
}
