using System.Collections.Immutable;
using System.Globalization;
using OperatorPanel.Core.Protocol.V3;

namespace OperatorPanel.Cli.Bench.V3;

/// <summary>
/// The time of one v3 exchange, part by part (docs/bench.md, "Protocol 3"): the request on the bus; until the reply's
/// first byte as the handler ran it in the interpreter (RCV's end timer END_TIMEOUT_MS, the receive interrupt, the
/// handler's scans each with the user's program), never before the cable has turned around; the reply on the bus with
/// its pauses; the PC's receive latency and the link's gap. By radio each module forwards a frame when Core's
/// <see cref="Reader"/> has it whole by its LEN (<see cref="LenRuleForwarder"/>), not at a byte's value.
/// </summary>
internal static class V3ExchangeTimes
{
    public static ExchangeTime Of(LinkTimeModel model, int endTimeoutMs, V3PlannedExchange planned, HandlerCost handler, IReadOnlyList<(byte Value, TimeSpan At)> reply, ICollection<string> problems)
    {
        ArgumentNullException.ThrowIfNull(model);
        ArgumentNullException.ThrowIfNull(planned);
        ArgumentNullException.ThrowIfNull(handler);
        ArgumentNullException.ThrowIfNull(reply);
        ArgumentNullException.ThrowIfNull(problems);
        var c = model.Line.CharacterMs;
        var character = TimeSpan.FromMilliseconds(c);
        var idleLimit = TimeSpan.FromMilliseconds(LenRuleForwarder.PartialFrameDropMs);
        var requestBytes = planned.Request.Length;
        var parts = ImmutableArray.CreateBuilder<TimePart>();
        if (model.Radio is { } radio)
        {
            var (whole, _) = LenRuleForwarder.Receive(LenRuleForwarder.BackToBack(planned.Request, character), character, idleLimit, Codec.MinRequestLen);
            parts.Add(new("USB frame to the FT232R", radio.UsbOutMs));
            parts.Add(new("request, PC module UART (forwarded when whole by its LEN)", (whole ?? character * requestBytes).TotalMilliseconds));
            parts.Add(new("request over the air", radio.AirMs(requestBytes)));
        }

        parts.Add(new("request on the bus", requestBytes * c));
        var first = Math.Max(handler.UntilFirstReply.TotalMilliseconds, model.TurnaroundMs);
        parts.Add(new(
            Invariant($"until the first reply byte: RCV's end timer {endTimeoutMs} ms, the receive interrupt, the handler's scans until it sends (of its {handler.Scans} for the request) with {model.ProgramScanMs:0.###} ms user program each (or the cable's turnaround if later)"),
            first));
        var onBus = handler.ReplyOnBus.TotalMilliseconds;
        var pauses = handler.Pauses(reply.Count, character).TotalMilliseconds;
        if (model.Radio is { } back)
        {
            // The PLC-side module forwards the reply once the LEN rule says it is whole; a pause longer than
            // PartialFrameDropMs inside it makes the module drop the partial frame (the reply is then lost).
            var (whole, dropped) = LenRuleForwarder.Receive(reply, character, idleLimit, Codec.MinReplyLen);
            var start = reply.Count == 0 ? TimeSpan.Zero : reply[0].At - character;
            if (whole is { } at && dropped == 0)
            {
                onBus = (at - start).TotalMilliseconds;
            }
            else
            {
                problems.Add(Invariant($"{planned.Name}: the PLC module dropped the reply: a pause inside it exceeded {LenRuleForwarder.PartialFrameDropMs} ms"));
            }

            parts.Add(new(Invariant($"reply on the bus until the PLC module has it whole by its LEN, {pauses:0.00} ms of it pauses between chunks"), onBus));
            parts.Add(new("reply over the air", back.AirMs(reply.Count)));
            parts.Add(new("reply, PC module UART", reply.Count * c));
            parts.Add(new("FT232R latency timer", back.LatencyTimerMs));
        }
        else
        {
            parts.Add(new(Invariant($"reply on the bus, {pauses:0.00} ms of it pauses between chunks"), onBus));
            parts.Add(new("PC UART FIFO timeout", CableTiming.FifoTimeoutCharacters * c));
        }

        parts.Add(new("link gap before the next request", model.GapMs));
        return new ExchangeTime(planned.Name, requestBytes, reply.Count, handler, parts.ToImmutable());
    }

    /// <summary>
    /// The same exchange with a PLC that takes no time at all: its reply starts the moment RCV's end timer has ended
    /// the request (or the cable has turned around) and leaves back to back. What the physics allows.
    /// </summary>
    public static ExchangeTime Floor(LinkTimeModel model, int endTimeoutMs, V3PlannedExchange planned)
    {
        ArgumentNullException.ThrowIfNull(model);
        ArgumentNullException.ThrowIfNull(planned);
        var character = TimeSpan.FromMilliseconds(model.Line.CharacterMs);
        var start = TimeSpan.FromMilliseconds(endTimeoutMs);
        var reply = new byte[planned.ReplyBytes];
        (reply[0], reply[1]) = (Limits.Start, (byte)planned.ReplyBytes);
        var timed = reply.Select((b, i) => (b, start + (character * (i + 1)))).ToList();
        var handler = new HandlerCost(0, start, character * planned.ReplyBytes, "none: a PLC that takes no time");
        return Of(model, endTimeoutMs, planned, handler, timed, []);
    }

    private static string Invariant(FormattableString text) => text.ToString(CultureInfo.InvariantCulture);
}
