using OperatorPanel.Core.Transport;

namespace OperatorPanel.ViewModels.Wizard;

/// <summary>A port in the link step's list. FTDI devices are marked: the radio module's PC side is an FT232R (seed 000 §6).</summary>
public sealed record PortChoice(SerialPortInfo Info)
{
    public string PortName => Info.PortName;

    public bool IsFtdi => Info.IsFtdi;

    /// <summary>"COM5 - FTDI USB serial (radio module or USB cable)"; many USB-RS485 cables use FTDI chips too.</summary>
    public string Label => IsFtdi ? $"{PortName} - FTDI USB serial (radio module or USB cable)" : PortName;
}
