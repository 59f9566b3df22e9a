using System.Globalization;

namespace OperatorPanel.Cli.Bench;

/// <summary>
/// The PC's end of a PPI bus as the PPI bench models it (docs/bench.md, "--ppi"). At 9.6 and 19.2 kbaud: the PC/PPI
/// cable on a COM port, as the Freeport bench has it: its turnaround (<see cref="CableTiming"/>, unconfirmed) before
/// any answer, and a 16550 UART handing over an answer's last characters 4 character times late. At 187.5 kbaud no COM
/// port's UART has the rate (a 16550 with its usual 1.8432 MHz clock stops at 115.2 kbaud) and the RS-232 PC/PPI cable
/// stops there too, so a USB-RS485 adapter with an FT232R is assumed (3 MHz / 16 = 187 500 exactly): a write reaches it
/// in the next USB frame (1 ms) and received characters wait for its latency timer (16 ms by default; FTDI AN232B-04),
/// with no turnaround (the adapter switches direction itself: an assumption). Before each frame the PC leaves the
/// 33-bit synchronisation pause PROFIBUS asks (felser.ch "Telegram sequences and time ratios").
/// </summary>
internal sealed record PpiPcSide(string Name, double WriteLatencyMs, double ReceiveLatencyMs, double TurnaroundMs)
{
    public const int SyncPauseBits = 33;

    public static PpiPcSide For(int baud, double usbLatencyMs)
    {
        var character = 11 * 1000.0 / baud;
        return baud <= 115_200
            ? new("PC/PPI cable on a COM port (16550 UART)", 0, CableTiming.FifoTimeoutCharacters * character, CableTiming.TurnaroundMs(baud))
            : new(string.Create(CultureInfo.InvariantCulture, $"USB-RS485 adapter (FT232R, latency timer {usbLatencyMs:0.#} ms)"), 1, usbLatencyMs, 0);
    }
}
