using System.Globalization;

namespace OperatorPanel.Core.Transport;

/// <summary>
/// Linux: every tty is in /sys/class/tty; one with a "device" link is backed by hardware. USB serial ports
/// (ttyUSB* from usb-serial drivers such as ftdi_sio, ttyACM* from cdc_acm) sit below the USB interface, whose
/// parent device directory holds idVendor and idProduct.
/// </summary>
public static partial class SerialPortDiscovery
{
    private static readonly string[] SerialPrefixes = ["ttyUSB", "ttyACM", "ttyS"];

    /// <summary>Symbolic links followed per path before giving up (the kernel's own limit).</summary>
    private const int MaxLinkHops = 40;

    /// <summary>Scans a sysfs tree; <paramref name="sysfsRoot"/> is "/sys" in production, a fake tree in tests.</summary>
    internal static IReadOnlyList<SerialPortInfo> ScanSysfs(string sysfsRoot)
    {
        var classDir = Path.Combine(sysfsRoot, "class", "tty");
        if (!Directory.Exists(classDir))
        {
            return [];
        }

        var root = ResolveLinks(sysfsRoot, 0);
        var ports = new List<SerialPortInfo>();
        foreach (var entry in Directory.EnumerateFileSystemEntries(classDir).Order(StringComparer.Ordinal))
        {
            var name = Path.GetFileName(entry);
            if (SerialPrefixes.Any(prefix => name.StartsWith(prefix, StringComparison.Ordinal))
                && TryDescribe(root, entry, out var vendor, out var product))
            {
                ports.Add(new SerialPortInfo("/dev/" + name, vendor, product));
            }
        }

        return ports;
    }

    private static bool TryDescribe(string root, string classEntry, out int? vendor, out int? product)
    {
        vendor = product = null;
        var device = Path.Combine(ResolveLinks(classEntry, 0), "device");
        if (!Directory.Exists(device))
        {
            return false;
        }

        device = ResolveLinks(device, 0);

        // The 8250 driver registers ttyS0-ttyS31 whether or not a UART exists; those phantoms hang off the
        // "platform" bus, real ones off pnp/pci/serial-base.
        var subsystem = Path.Combine(device, "subsystem");
        if (Path.GetFileName(classEntry).StartsWith("ttyS", StringComparison.Ordinal)
            && new FileInfo(subsystem).LinkTarget is { } bus && Path.GetFileName(bus) == "platform")
        {
            return false;
        }

        for (var dir = device; dir.StartsWith(root, StringComparison.Ordinal) && dir.Length > root.Length;
             dir = Path.GetDirectoryName(dir) ?? root)
        {
            if (File.Exists(Path.Combine(dir, "idVendor")))
            {
                vendor = ReadHex(Path.Combine(dir, "idVendor"));
                product = ReadHex(Path.Combine(dir, "idProduct"));
                break;
            }
        }

        return true;
    }

    private static int? ReadHex(string file) =>
        File.Exists(file) && int.TryParse(File.ReadAllText(file).Trim(), NumberStyles.HexNumber, CultureInfo.InvariantCulture, out var value)
            ? value
            : null;

    /// <summary>realpath(3) in managed code: sysfs links are relative to the real directory of the link.</summary>
    private static string ResolveLinks(string path, int hops)
    {
        var full = Path.GetFullPath(path);
        var result = Path.GetPathRoot(full) ?? "/";
        foreach (var part in full[result.Length..].Split(Path.DirectorySeparatorChar, StringSplitOptions.RemoveEmptyEntries))
        {
            var next = Path.Combine(result, part);
            if (new FileInfo(next).LinkTarget is { } target && hops < MaxLinkHops)
            {
                next = ResolveLinks(Path.IsPathRooted(target) ? target : Path.Combine(result, target), hops + 1);
            }

            result = next;
        }

        return result;
    }
}
