using System.Globalization;

namespace OperatorPanel.Cli.Bench;

/// <summary>
/// The 433 MHz radio module pair of seed 000 section 6: PC, USB, FT232R, ATmega16L, CC1100 ... CC1100, ATmega16L,
/// MAX232, PC/PPI cable, PLC. Each module's MCU receives a frame whole (from '&lt;' to '&gt;') before it sends it on,
/// in both directions, so a frame crosses the bus baud rate twice (the PC-side UART and the PLC-side UART) plus the air.
/// </summary>
/// <param name="AirBaud">
/// The CC1100 data rate. Seed 000 does not give it. Assumed 38 400 baud, one of the chip's usual settings (it ranges
/// 1.2-500 kBaud; its reset value is 115.051 kBaud with a 26 MHz crystal), chosen on the slow side.
/// </param>
/// <param name="PacketOverheadBytes">
/// Bytes the CC1100 sends besides the frame: the reset settings' 4 preamble bytes, 2 sync word bytes, 1 length byte
/// (variable packet length) and 2 CRC bytes (CC1101 data sheet SWRS061, register reset values MDMCFG1, MDMCFG2, PKTCTRL0).
/// </param>
/// <param name="TxStartMs">
/// From the MCU's transmit strobe to the first preamble bit: IDLE to TX with frequency-synthesiser calibration, 799 us
/// (CC1101 data sheet SWRS061I, Table 34; the CC1100 is its predecessor). Conservative: calibrated before every packet.
/// </param>
/// <param name="UsbOutMs">A write from the PC reaches the FT232R in the next USB full-speed frame, up to 1 ms.</param>
/// <param name="LatencyTimerMs">
/// The FT232R passes received characters to the PC when 62 have gathered or its latency timer runs out, 16 ms by
/// default, counted from the last transfer to the PC; the end of a reply therefore waits up to 16 ms (FTDI AN232B-04
/// "Data Throughput, Latency and Handshaking", section "Small Amounts of Data and End of Buffer Conditions"). The
/// worst case is modelled.
/// </param>
internal sealed record RadioModuleTiming(double AirBaud, int PacketOverheadBytes, double TxStartMs, double UsbOutMs, double LatencyTimerMs)
{
    public static RadioModuleTiming Default { get; } = new(38_400, 9, 0.799, 1, 16);

    /// <summary>One radio hop of a frame of <paramref name="chars"/> characters: start of transmission, then the packet's bits.</summary>
    public double AirMs(int chars) => TxStartMs + ((PacketOverheadBytes + chars) * 8 * 1000.0 / AirBaud);

    public override string ToString() => string.Create(
        CultureInfo.InvariantCulture,
        $"air {AirBaud / 1000:0.###} kBaud (assumed), {PacketOverheadBytes} bytes packet overhead, TX start {TxStartMs:0.###} ms, USB out {UsbOutMs:0.#} ms, FT232R latency timer {LatencyTimerMs:0.#} ms");
}
