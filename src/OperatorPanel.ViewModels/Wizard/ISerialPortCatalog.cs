using OperatorPanel.Core.Transport;

namespace OperatorPanel.ViewModels.Wizard;

/// <summary>The serial ports present, for the link step's list; <see cref="SystemSerialPortCatalog"/> asks the OS.</summary>
public interface ISerialPortCatalog
{
    IReadOnlyList<SerialPortInfo> List();
}
