using OperatorPanel.Core.Protocol.V3;

namespace OperatorPanel.Cli.Bench.V3;

/// <summary>
/// A radio module's receiving side for v3 (docs/protocol.md section 1.6): it cuts frames with Core's
/// <see cref="Reader"/> (the LEN rule: '&lt;', LEN, then LEN bytes in all, whatever their values) and forgets a partial
/// frame after an idle line longer than <see cref="PartialFrameDropMs"/>. Fed the bytes with the time each one's stop
/// bit ended, it says when the frame came out whole (the module may then send it on) or that a pause inside the frame
/// made it drop it.
/// </summary>
internal static class LenRuleForwarder
{
    /// <summary>
    /// A module forgets a partial frame after this long without a byte (docs/protocol.md section 1.6). A v3 reply leaves
    /// in chunks: its head and payload first, its check when the handler has computed it, a few double words a scan,
    /// so the pause before the check can last several scans of the CPU (section 7; the bench's handler runs show 11
    /// scans of check for a whole list of 76 bytes, less the payload's own time on the wire). One second covers that
    /// for machine programs of up to about 90 ms a scan. The drop is only for a byte lost on a module's wired side
    /// (the air carries whole frames as packets). Dropping after END_TIMEOUT_MS (the first rule) lost every whole-list
    /// reply once a scan took 10 ms.
    /// </summary>
    public const int PartialFrameDropMs = 1000;

    /// <returns>The time the frame was whole, or null when it never was; and the partial frames dropped on a pause.</returns>
    public static (TimeSpan? Whole, int Dropped) Receive(IReadOnlyList<(byte Value, TimeSpan At)> bytes, TimeSpan characterTime, TimeSpan idleLimit, int minLen)
    {
        ArgumentNullException.ThrowIfNull(bytes);
        var reader = new Reader(minLen);
        var dropped = 0;
        TimeSpan? last = null;
        foreach (var (value, at) in bytes)
        {
            // The line was idle from the previous stop bit to this byte's start bit.
            if (last is { } previous && reader.PendingBytes > 0 && at - characterTime - previous > idleLimit)
            {
                reader.Reset();
                dropped++;
            }

            reader.Append([value]);
            last = at;
            if (reader.TryTake(out _))
            {
                return (at, dropped);
            }
        }

        return (null, dropped);
    }

    /// <summary>Bytes sent back to back from time 0 (a PC's write, a module's forwarding), each with its stop bit's end.</summary>
    public static IReadOnlyList<(byte Value, TimeSpan At)> BackToBack(byte[] frame, TimeSpan characterTime)
    {
        ArgumentNullException.ThrowIfNull(frame);
        return [.. frame.Select((b, i) => (b, characterTime * (i + 1)))];
    }
}
