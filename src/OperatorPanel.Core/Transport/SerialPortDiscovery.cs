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

        return OperatingSystem.IsLinux() ? ScanSysfs("/sys") : ScanDevCallOut("/dev");
    }

    /// <summary>
    /// macOS (and other Unix): the call-out devices /dev/cu.*. Their names do not identify the USB vendor reliably
    /// (FTDI, Prolific and others all appear as cu.usbserial-*), so the vendor stays unknown.
    /// </summary>
    internal static IReadOnlyList<SerialPortInfo> ScanDevCallOut(string devRoot) =>
        !Directory.Exists(devRoot)
            ? []
            : Directory.EnumerateFileSystemEntries(devRoot, "cu.*")
                .Order(StringComparer.Ordinal)
                .Select(path => new SerialPortInfo(path, null, null))
                .ToList();
}
