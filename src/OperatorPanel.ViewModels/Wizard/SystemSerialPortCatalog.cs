using OperatorPanel.Core.Transport;

namespace OperatorPanel.ViewModels.Wizard;

/// <summary>The ports the OS publishes now (<see cref="SerialPortDiscovery"/>); opens none.</summary>
public sealed class SystemSerialPortCatalog : ISerialPortCatalog
{
    public IReadOnlyList<SerialPortInfo> List() => SerialPortDiscovery.List();
}
