using OperatorPanel.Core.Transport;

namespace OperatorPanel.Core.Tests.Transport;

/// <summary>Runs the Linux sysfs scan on a fake tree shaped like the kernel's (relative links, USB parents).</summary>
public sealed class SerialPortDiscoveryTests : IDisposable
{
    private readonly string _root = Directory.CreateTempSubdirectory("opanel-sysfs-").FullName;

    public SerialPortDiscoveryTests()
    {
        // FT232R on ftdi_sio: class entry -> .../1-1/1-1:1.0/ttyUSB0/tty/ttyUSB0, device -> the usb-serial port,
        // whose grandparent 1-1 is the USB device with idVendor/idProduct.
        var usb = Dir("devices/pci0000:00/usb1/1-1");
        File.WriteAllText(Path.Combine(usb, "idVendor"), "0403\n");
        File.WriteAllText(Path.Combine(usb, "idProduct"), "6001\n");
        Dir("devices/pci0000:00/usb1/1-1/1-1:1.0/ttyUSB0/tty/ttyUSB0");
        Link("devices/pci0000:00/usb1/1-1/1-1:1.0/ttyUSB0/tty/ttyUSB0/device", "../../../ttyUSB0");

        // A CDC-ACM device (not FTDI): device -> the USB interface directly.
        var acm = Dir("devices/pci0000:00/usb1/1-2");
        File.WriteAllText(Path.Combine(acm, "idVendor"), "2341\n");
        File.WriteAllText(Path.Combine(acm, "idProduct"), "0043\n");
        Dir("devices/pci0000:00/usb1/1-2/1-2:1.0/tty/ttyACM0");
        Link("devices/pci0000:00/usb1/1-2/1-2:1.0/tty/ttyACM0/device", "../../../1-2:1.0");

        // ttyS0 registered by the kernel without hardware behind it: no device link.
        Dir("devices/virtual/tty/ttyS0");
        Dir("devices/virtual/tty/tty0");

        // ttyS1 of the 8250 driver with no UART: its device is the "platform" bus placeholder.
        Dir("bus/platform");
        Dir("devices/platform/serial8250/tty/ttyS1");
        Link("devices/platform/serial8250/subsystem", "../../../bus/platform");
        Link("devices/platform/serial8250/tty/ttyS1/device", "../../../serial8250");

        Dir("class/tty");
        Link("class/tty/ttyUSB0", "../../devices/pci0000:00/usb1/1-1/1-1:1.0/ttyUSB0/tty/ttyUSB0");
        Link("class/tty/ttyACM0", "../../devices/pci0000:00/usb1/1-2/1-2:1.0/tty/ttyACM0");
        Link("class/tty/ttyS0", "../../devices/virtual/tty/ttyS0");
        Link("class/tty/tty0", "../../devices/virtual/tty/tty0");
        Link("class/tty/ttyS1", "../../devices/platform/serial8250/tty/ttyS1");
    }

    [Fact]
    public void ScanSysfs_FakeTree_ListsPortsWithRealHardwareOnly()
    {
        var ports = SerialPortDiscovery.ScanSysfs(_root);

        ports.Select(p => p.PortName).Should().Equal("/dev/ttyACM0", "/dev/ttyUSB0");
    }

    [Fact]
    public void ScanSysfs_FtdiAdapter_IsMarkedFtdiWithItsProduct()
    {
        var usb0 = SerialPortDiscovery.ScanSysfs(_root).Single(p => p.PortName == "/dev/ttyUSB0");

        usb0.Should().Be(new SerialPortInfo("/dev/ttyUSB0", 0x0403, 0x6001));
        usb0.IsFtdi.Should().BeTrue();
    }

    [Fact]
    public void ScanSysfs_CdcAcmDevice_IsNotFtdi()
    {
        var acm0 = SerialPortDiscovery.ScanSysfs(_root).Single(p => p.PortName == "/dev/ttyACM0");

        acm0.UsbVendorId.Should().Be(0x2341);
        acm0.IsFtdi.Should().BeFalse();
    }

    [Fact]
    public void ScanSysfs_MissingTree_ReturnsEmpty()
    {
        SerialPortDiscovery.ScanSysfs(Path.Combine(_root, "absent")).Should().BeEmpty();
    }

    [Fact]
    public void CallOutDevices_MacPortNames_KeepsOnlyCallOutDevicesInOrder()
    {
        var ports = SerialPortDiscovery.CallOutDevices(["/dev/tty.usbserial-A50285BI", "/dev/cu.usbserial-A50285BI", "/dev/cu.Bluetooth-Incoming-Port"]);

        ports.Should().Equal(new SerialPortInfo("/dev/cu.Bluetooth-Incoming-Port", null, null), new SerialPortInfo("/dev/cu.usbserial-A50285BI", null, null));
    }

    public void Dispose() => Directory.Delete(_root, recursive: true);

    private string Dir(string relative) => Directory.CreateDirectory(Path.Combine(_root, relative)).FullName;

    private void Link(string relative, string target) => Directory.CreateSymbolicLink(Path.Combine(_root, relative), target);
}
