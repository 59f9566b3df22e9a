namespace OperatorPanel.Core.Transport;

/// <summary>
/// Lists the serial ports present, marking FTDI devices (the FT232R radio module of seed 000 §6), for the wizard's
/// port list and `opanel ports`. Reads what the OS publishes; opens no port.
/// </summary>
public static partial class SerialPortDiscovery
{
    /// <summary>The ports present now, ordered by name. Empty when the OS publishes none.</summary>
    public static IReadOnlyList<SerialPortInfo> List()
    {
        if (OperatingSystem.IsWindows())
        {
            return ScanRegistry();
        }

        return OperatingSystem.IsLinux() ? ScanSysfs("/sys") : CallOutDevices(SerialPortTransport.PortNamesPresent());
    }

    /// <summary>
    /// macOS (and other Unix): the call-out devices /dev/cu.* (the /dev/tty.* twins wait for carrier on open). Their
    /// names do not identify the USB vendor reliably (FTDI, Prolific and others all appear as cu.usbserial-*), so the
    /// vendor stays unknown.
    /// </summary>
    internal static IReadOnlyList<SerialPortInfo> CallOutDevices(IEnumerable<string> portNames) =>
        portNames
            .Where(name => name.StartsWith("/dev/cu.", StringComparison.Ordinal))
            .Order(StringComparer.Ordinal)
            .Select(path => new SerialPortInfo(path, null, null))
            .ToList();
}
