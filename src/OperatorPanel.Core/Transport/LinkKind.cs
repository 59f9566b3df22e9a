namespace OperatorPanel.Core.Transport;

/// <summary>How the PC reaches the RS-485 bus.</summary>
public enum LinkKind
{
    /// <summary>PC/PPI (RS-232/PPI Multi-Master) or USB-RS485 cable on a COM port.</summary>
    Cable,

    /// <summary>The 433 MHz radio module pair of seed 000; the PC side is an FTDI FT232R USB serial device.</summary>
    RadioModule,
}
