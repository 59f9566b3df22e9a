using System.Globalization;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Simulator.Reference;

/// <summary>
/// What RCV hands the handler: every character from the first '&lt;' to the '&gt;', a second '&lt;' included (RCV
/// does not restart). The receive interrupt's early silence looks at the FIRST '&lt;'; the frame the handler checks
/// starts at the LAST '&lt;' (docs/protocol-v2.md, "Processing order", steps 1-2).
/// </summary>
public static class ReceivedMessage
{
    /// <summary>Message index of CMD's first character: '&lt;' S S Q Q C.</summary>
    private const int CommandHigh = 5;

    /// <summary>
    /// True when the receive interrupt re-arms RCV at once: the two characters after the first '&lt;' are not the
    /// station as two uppercase hex digits, or CMD's first character is '8'-'9' or 'A'-'F' (a reply). A message too
    /// short to hold those characters is silenced here too (it is shorter than any frame, so silent either way).
    /// </summary>
    public static bool SilencedEarly(ReadOnlySpan<byte> received, Station station)
    {
        var own = station.Address.ToString("X2", CultureInfo.InvariantCulture);
        return received.Length <= CommandHigh
            || received[1] != own[0] || received[2] != own[1]
            || received[CommandHigh] is (>= (byte)'8' and <= (byte)'9') or (>= (byte)'A' and <= (byte)'F');
    }

    /// <summary>The frame the handler checks: from the last '&lt;' to the end (the earlier characters are a cut-off frame).</summary>
    public static ReadOnlySpan<byte> LastFrame(ReadOnlySpan<byte> received) => received[received.LastIndexOf(FrameCodec.StartChar)..];
}
