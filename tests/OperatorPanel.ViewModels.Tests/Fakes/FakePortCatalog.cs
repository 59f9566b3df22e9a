using OperatorPanel.Core.Transport;
using OperatorPanel.ViewModels.Wizard;

namespace OperatorPanel.ViewModels.Tests.Fakes;

/// <summary>Two ports: COM3 (a PC/PPI cable's USB-serial, Prolific) and COM7 (an FTDI FT232R, the radio module).</summary>
internal sealed class FakePortCatalog : ISerialPortCatalog
{
    public List<SerialPortInfo> Ports { get; } = [new("COM3", 0x067B, 0x2303), new("COM7", SerialPortInfo.FtdiVendorId, 0x6001)];

    public IReadOnlyList<SerialPortInfo> List() => [.. Ports];
}
