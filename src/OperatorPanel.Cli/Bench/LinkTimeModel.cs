using System.Collections.Immutable;
using System.Globalization;

namespace OperatorPanel.Cli.Bench;

/// <summary>
/// The time of one exchange on a half-duplex line, part by part, with nothing invented: the request at the line's
/// character time; the PLC's side as the handler in the interpreter ran it (<see cref="HandlerCost"/>: until the reply's
/// first character, and the reply on the bus with its pauses), never starting before the cable has turned around; the
/// PC's receive latency, and the link's gap before the next request. With <see cref="Radio"/> set, the radio module
/// pair's store-and-forward hops, air time and FT232R latency timer too: the PLC-side module forwards the reply only
/// once its '&gt;' has arrived.
/// </summary>
/// <param name="Line">Baud rate and character format of the bus (and of both radio module UARTs).</param>
/// <param name="ReplyDelayMs">The handler's reply delay (timed interrupt 0, SMB34), counted from the first pass of the reply's check.</param>
/// <param name="ProgramScanMs">
/// The user program's own time per scan, run in the interpreter beside the handler (<see cref="HandlerProbe"/>): the
/// handler serves a request one slice per scan, so each of its scans also runs the user's program. An assumption
/// about the line (a real line reports it in SMW22-SMW26).
/// </param>
/// <param name="LinkGapMs">
/// The gap the PC's link keeps after a reply before the next request (LinkOptions); the model never lets it be shorter
/// than the protocol's minimum: 5 ms and 3 character times (docs/protocol-v2.md, "Minimum gap").
/// </param>
/// <param name="Radio">The radio module pair between the PC and the bus; null for the PC/PPI cable.</param>
internal sealed record LinkTimeModel(LineSetting Line, double ReplyDelayMs, double ProgramScanMs, double LinkGapMs, RadioModuleTiming? Radio)
{
    public const double MinimumGapMs = 5;
    public const int MinimumGapCharacters = 3;

    public double GapMs => Math.Max(LinkGapMs, Math.Max(MinimumGapMs, MinimumGapCharacters * Line.CharacterMs));

    public double TurnaroundMs => CableTiming.TurnaroundMs(Line.Baud);

    public ExchangeTime Exchange(string name, int requestChars, int replyChars, HandlerCost handler)
    {
        ArgumentNullException.ThrowIfNull(handler);
        var c = Line.CharacterMs;
        var parts = ImmutableArray.CreateBuilder<TimePart>();
        if (Radio is { } radio)
        {
            parts.Add(new("USB frame to the FT232R", radio.UsbOutMs));
            parts.Add(new("request, PC module UART (received whole)", requestChars * c));
            parts.Add(new("request over the air", radio.AirMs(requestChars)));
        }

        parts.Add(new("request on the bus", requestChars * c));

        // The reply may not start before the cable has switched back to receive.
        parts.Add(new(
            Invariant($"until the first reply character: handler slices, {ProgramScanMs:0.###} ms user program per scan, reply delay (or the cable's turnaround if later); {handler.Scans} handler scans in all"),
            Math.Max(handler.UntilFirstReply.TotalMilliseconds, TurnaroundMs)));
        var pauses = handler.Pauses(replyChars, TimeSpan.FromMilliseconds(c)).TotalMilliseconds;
        parts.Add(new(Invariant($"reply on the bus, {pauses:0.00} ms of it pauses while the handler computes its check"), handler.ReplyOnBus.TotalMilliseconds));
        if (Radio is { } back)
        {
            parts.Add(new("reply over the air (PLC module received it whole)", back.AirMs(replyChars)));
            parts.Add(new("reply, PC module UART", replyChars * c));
            parts.Add(new("FT232R latency timer", back.LatencyTimerMs));
        }
        else
        {
            parts.Add(new("PC UART FIFO timeout", CableTiming.FifoTimeoutCharacters * c));
        }

        parts.Add(new("link gap before the next request", GapMs));
        return new ExchangeTime(name, requestChars, replyChars, handler, parts.ToImmutable());
    }

    private static string Invariant(FormattableString text) => text.ToString(CultureInfo.InvariantCulture);
}
