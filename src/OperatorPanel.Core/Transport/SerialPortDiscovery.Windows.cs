using System.Globalization;
using System.Runtime.Versioning;
using Microsoft.Win32;

namespace OperatorPanel.Core.Transport;

/// <summary>
/// Windows: the COM ports present come from the serial library (HKLM\HARDWARE\DEVICEMAP\SERIALCOMM). The FTDI
/// driver enumerates its devices under HKLM\SYSTEM\CurrentControlSet\Enum\FTDIBUS\VID_0403+PID_xxxx+serial\0000,
/// whose "Device Parameters" key holds the PortName it was given: that is what marks a port as FTDI.
/// </summary>
public static partial class SerialPortDiscovery
{
    [SupportedOSPlatform("windows")]
    private static List<SerialPortInfo> ScanRegistry()
    {
        var ftdi = FtdiPortProducts();
        return SerialPortTransport.PortNamesPresent()
            .Distinct(StringComparer.OrdinalIgnoreCase)
            .Order(StringComparer.OrdinalIgnoreCase)
            .Select(port => ftdi.TryGetValue(port, out var product)
                ? new SerialPortInfo(port, SerialPortInfo.FtdiVendorId, product)
                : new SerialPortInfo(port, null, null))
            .ToList();
    }

    /// <summary>COM name → USB product id of every FTDI device the driver has ever enumerated.</summary>
    [SupportedOSPlatform("windows")]
    private static Dictionary<string, int?> FtdiPortProducts()
    {
        var result = new Dictionary<string, int?>(StringComparer.OrdinalIgnoreCase);
        using var bus = Registry.LocalMachine.OpenSubKey(@"SYSTEM\CurrentControlSet\Enum\FTDIBUS");
        foreach (var deviceName in bus?.GetSubKeyNames() ?? [])
        {
            if (!deviceName.StartsWith("VID_0403", StringComparison.OrdinalIgnoreCase))
            {
                continue;
            }

            using var device = bus!.OpenSubKey(deviceName);
            foreach (var instance in device?.GetSubKeyNames() ?? [])
            {
                using var parameters = device!.OpenSubKey(instance + @"\Device Parameters");
                if (parameters?.GetValue("PortName") is string port)
                {
                    result[port] = ProductOf(deviceName);
                }
            }
        }

        return result;
    }

    /// <summary>"VID_0403+PID_6001+A50285BI" → 16#6001.</summary>
    private static int? ProductOf(string deviceName)
    {
        var at = deviceName.IndexOf("PID_", StringComparison.OrdinalIgnoreCase);
        return at >= 0 && deviceName.Length >= at + 8
            && int.TryParse(deviceName.AsSpan(at + 4, 4), NumberStyles.HexNumber, CultureInfo.InvariantCulture, out var pid)
            ? pid
            : null;
    }
}
