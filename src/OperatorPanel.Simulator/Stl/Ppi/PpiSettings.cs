using OperatorPanel.Core.Ppi;
using OperatorPanel.Core.Transport;
using OperatorPanel.Simulator.Stl.Freeport;

namespace OperatorPanel.Simulator.Stl.Ppi;

/// <summary>
/// The PPI side of a simulated CPU's port, as its system block would set it (docs/ppi.md section 11): the PPI address
/// (a CPU's default is 2) and baud rate (9.6, 19.2 or 187.5 kbaud), always 8 data bits, even parity, one stop bit.
/// </summary>
public sealed record PpiSettings
{
    private readonly TimeSpan? _stationDelay;

    /// <summary>The PPI baud rates of the S7-200 CPUs (seed 002, Tables: "PPI/MPI baud rates 9.6, 19.2, and 187.5 kbaud").</summary>
    public static readonly IReadOnlyList<int> BaudRates = [9600, 19200, 187500];

    public PpiSettings(int address = 2, int baud = 9600)
    {
        ArgumentOutOfRangeException.ThrowIfNegative(address);
        ArgumentOutOfRangeException.ThrowIfGreaterThan(address, PpiFrame.MaxAddress);
        if (!BaudRates.Contains(baud))
        {
            throw new ArgumentOutOfRangeException(nameof(baud), baud, "PPI runs at 9600, 19200 or 187500 baud");
        }

        Address = address;
        Baud = baud;
    }

    public int Address { get; }

    public int Baud { get; }

    /// <summary>11-bit characters: start, 8 data, even parity, stop (ML801761 p. 228).</summary>
    public LineSettings Line => new(Baud, Parity.Even, 8);

    /// <summary>
    /// Time from the end of a master's frame to the start of the CPU's answer: by default 11 bit times, PROFIBUS's
    /// default minimum station delay (min TSDR, felser.ch "Telegram sequences and time ratios"). No S7-200 figure is
    /// published (unconfirmed); the bench raises it to the PC/PPI cable's turnaround.
    /// </summary>
    public TimeSpan StationDelay
    {
        get => _stationDelay ?? Line.Bits(11);
        init => _stationDelay = value;
    }

    /// <summary>The PDU size the CPU agrees to and takes (unconfirmed for the S7-200: 240, PpiLimits.DefaultPduSize).</summary>
    public int PduSize { get; init; } = PpiLimits.DefaultPduSize;

    /// <summary>A telegram whose characters stop for this long is dropped (unconfirmed; generous for USB adapters and ptys).</summary>
    public TimeSpan PartialFrameTimeout { get; init; } = TimeSpan.FromMilliseconds(50);

    /// <summary>
    /// How often a CPU in STOP serves the communication phase. Its STOP scan is not published (unconfirmed); 1 ms, so a
    /// CPU in STOP answers at its first poll or the next.
    /// </summary>
    public TimeSpan StopCycle { get; init; } = TimeSpan.FromMilliseconds(1);

    /// <summary>The setting for a line at <paramref name="baud"/>: that rate where PPI has it, else 9600.</summary>
    public static PpiSettings ForLine(int address, int baud) => new(address, BaudRates.Contains(baud) ? baud : 9600);
}
