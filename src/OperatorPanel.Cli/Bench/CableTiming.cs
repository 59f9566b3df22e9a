namespace OperatorPanel.Cli.Bench;

/// <summary>
/// The PC/PPI cable between a PC's serial port and the RS-485 bus, and the PC's own UART.
/// <para>
/// Turnaround: the cable sends RS-232 to RS-485 while the PC transmits and switches back to receive only after the line
/// has been quiet for its turnaround time; a reply that starts earlier is lost. No primary source was found for the
/// figures (docs/sources/s7200-facts.md section 7, marked [U]); the larger of the remembered values is used:
/// 28 ms at 1200 baud halving with each doubling of the rate (4 ms at 9600, 1 ms at 38400). It costs time only when
/// the handler's work and reply delay are shorter than it.
/// </para>
/// <para>
/// PC receive: a 16550-type UART interrupts when its FIFO reaches the trigger level or, for the last few characters
/// of a reply, when no character has arrived for 4 character times (TI TL16C550C data sheet, "FIFO interrupt mode
/// operation"), so the reply's end reaches the PC up to 4 character times late.
/// </para>
/// </summary>
internal static class CableTiming
{
    public const int FifoTimeoutCharacters = 4;

    private static readonly (int Baud, double Ms)[] Turnarounds =
        [(1200, 28), (2400, 14), (4800, 7), (9600, 4), (19200, 2), (38400, 1), (57600, 0.5), (115200, 0.25)];

    /// <summary>The turnaround at <paramref name="baud"/>; between table rows the slower row's figure (the larger).</summary>
    public static double TurnaroundMs(int baud) =>
        Turnarounds.Where(t => t.Baud <= baud).Select(t => t.Ms).DefaultIfEmpty(Turnarounds[0].Ms).Min();
}
