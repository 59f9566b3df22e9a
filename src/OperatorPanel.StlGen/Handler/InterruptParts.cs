using OperatorPanel.StlGen.Model;
using static OperatorPanel.StlGen.Handler.HandlerContext;
using static OperatorPanel.StlGen.Handler.HandlerLayout;

namespace OperatorPanel.StlGen.Handler;

/// <summary>
/// The two short interrupt routines of the reply (<see cref="ChunkPart"/>): the reply delay (timed interrupt 0, event
/// 10) sends the first chunk; transmit complete (event 9 / 26) sends the characters the check has covered since, or,
/// after the chunk that ended with the '&gt;', starts receiving again. RCV and XMT are never active together
/// (half-duplex RS-485, seed 001). The routines use AC0: the CPU saves and reloads the accumulators around every
/// interrupt routine (docs/sources/s7200-facts.md section 5).
/// </summary>
internal static class InterruptParts
{
    public static StlNetwork Delay(HandlerContext c) =>
        new NetworkBuilder(
                "Reply delay over: send the first chunk",
                $"Runs {c.Options.ReplyDelayMs} ms after the reply check's first pass, so a PC/PPI cable can turn around. Detach event 10",
                "first (timed interrupts repeat), then transmit buffer bytes 1 .. COVERED, byte 0 (SENT) = their count.")
            .Op("LD", "SM0.0").Op("DTCH", Dec(DelayEvent)).SendCovered(c).Build();

    public static IEnumerable<StlNetwork> Transmit(HandlerContext c)
    {
        var l = c.Layout;
        yield return new NetworkBuilder(
                "Chunk sent: send what the check has covered since",
                "COVERED past SENT: the next chunk, its table the character at SENT (on the wire already); bit 2 stays set.")
            .Op("LDD<>", l.Dw(Covered), l.Dw(Sent)).SendCovered(c).Op("CRETI").Build();
        yield return new NetworkBuilder(
                "Chunk sent, the check not further yet",
                $"SENT is no '>': clear bit {SendingBit}, OP_PANEL sends the next chunk after its next pass.")
            .Op("LDB<>", "*" + l.Dw(Sent), "16#3E").Op("R", l.Bit(StopState, SendingBit), "1").Op("CRETI").Build();
        var net = new NetworkBuilder("Reply sent: receive again", "The chunk ended with the '>': listen for the next request.")
            .Op("LD", "SM0.0").Op("RCV", l.B(0), c.PortOperand);
        StopPart.MarkSent(c, net);
        yield return net.Build();
    }
}
