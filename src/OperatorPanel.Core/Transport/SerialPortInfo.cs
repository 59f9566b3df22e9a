namespace OperatorPanel.Core.Transport;

/// <summary>
/// A serial port present on this PC. <see cref="IsFtdi"/> marks FTDI USB devices (vendor 16#0403), which is what the
/// radio module of seed 000 §6 shows up as (FT232R); many USB-RS485 cables use FTDI chips too.
/// </summary>
/// <param name="PortName">"COM5" on Windows, "/dev/ttyUSB0" on Linux: what <see cref="SerialSettings.PortName"/> takes.</param>
/// <param name="UsbVendorId">USB idVendor when known (Linux sysfs; Windows FTDI driver entries).</param>
/// <param name="UsbProductId">USB idProduct when known; 16#6001 is the FT232R.</param>
public sealed record SerialPortInfo(string PortName, int? UsbVendorId, int? UsbProductId)
{
    /// <summary>FTDI's USB vendor id.</summary>
    public const int FtdiVendorId = 0x0403;

    public bool IsFtdi => UsbVendorId == FtdiVendorId;
}
