using OperatorPanel.Core.Transport;

namespace OperatorPanel.Core.Link.V3;

/// <summary>
/// The link options of a protocol v3 bus (docs/protocol.md section 7). The reply time-out counts the station's
/// END_TIMEOUT_MS (SMW92: its receive ends that long after the request's last character, and no reply starts earlier)
/// where v2 counted its reply delay; the gap before a request is at least END_TIMEOUT_MS plus one character, or the
/// request would still fall into the RCV message of the frame before it, and never shorter than v2's minimum gap (a
/// delayed receive interrupt).
/// </summary>
public static class V3LinkOptions
{
    /// <summary>
    /// END_TIMEOUT_MS a handler is generated with unless told otherwise (HandlerOptions in StlGen): one character
    /// rounded down plus 2 ms (the timer counts whole ms, so it must outlast a character by more than 1 ms), and at
    /// least the PC/PPI cable's turnaround, 28 ms at 1200 baud halving per doubling, rounded up
    /// (docs/sources/s7200-facts.md section 7, unconfirmed: the larger figures are taken).
    /// </summary>
    public static int DefaultEndTimeoutMs(int baudRate, Parity parity, int dataBits)
    {
        ArgumentOutOfRangeException.ThrowIfNegativeOrZero(baudRate);
        var characterMs = 1000.0 * (2 + dataBits + (parity == Parity.None ? 0 : 1)) / baudRate;
        var turnaroundMs = (int)Math.Ceiling(28.0 * 1200 / baudRate);
        return Math.Max((int)Math.Floor(characterMs) + 2, turnaroundMs);
    }

    /// <summary>The default END_TIMEOUT_MS on <paramref name="serial"/>'s baud, parity and data bits.</summary>
    public static int DefaultEndTimeoutMs(SerialSettings serial)
    {
        ArgumentNullException.ThrowIfNull(serial);
        return DefaultEndTimeoutMs(serial.BaudRate, serial.Parity, serial.DataBits);
    }

    /// <summary>
    /// <see cref="LinkOptions.For"/> for a v3 bus whose stations end a receive after <paramref name="endTimeoutMs"/>
    /// (null: the default for the line), with the gap raised to END_TIMEOUT_MS + one character where that is longer.
    /// </summary>
    public static LinkOptions For(SerialSettings serial, int? endTimeoutMs = null)
    {
        ArgumentNullException.ThrowIfNull(serial);
        var end = endTimeoutMs ?? DefaultEndTimeoutMs(serial);
        ArgumentOutOfRangeException.ThrowIfNegativeOrZero(end, nameof(endTimeoutMs));
        ArgumentOutOfRangeException.ThrowIfGreaterThan(end, byte.MaxValue, nameof(endTimeoutMs));
        var options = LinkOptions.For(serial, (byte)end);
        var gap = MinimumGap(serial, end);
        return gap > options.InterFrameGap ? options with { InterFrameGap = gap } : options;
    }

    /// <summary>END_TIMEOUT_MS + one character time: the least quiet time before a request that no station's RCV merges with the frame before.</summary>
    public static TimeSpan MinimumGap(SerialSettings serial, int endTimeoutMs)
    {
        ArgumentNullException.ThrowIfNull(serial);
        return TimeSpan.FromMilliseconds(endTimeoutMs) + serial.CharacterTime;
    }
}
