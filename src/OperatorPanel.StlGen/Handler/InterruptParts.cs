using OperatorPanel.StlGen.Model;
using static OperatorPanel.StlGen.Handler.HandlerContext;

namespace OperatorPanel.StlGen.Handler;

/// <summary>
/// The two short interrupt routines: the reply delay (timed interrupt 0, event 10) sends the reply; transmit complete
/// (event 9 / 26) starts receiving again. RCV and XMT are never active together (half-duplex RS-485, seed 001).
/// </summary>
internal static class InterruptParts
{
    public static StlNetwork Delay(HandlerContext c) =>
        new NetworkBuilder(
                "Reply delay over: send the reply",
                $"Runs {c.Options.ReplyDelayMs} ms after the request was checked, so a PC/PPI cable can turn around.",
                "Detach event 10 first (timed interrupts repeat), then transmit the buffer (byte 0 = count).")
            .Op("LD", "SM0.0").Op("DTCH", Dec(DelayEvent)).Op("XMT", c.Layout.B(0), c.PortOperand).Build();

    public static StlNetwork Transmit(HandlerContext c)
    {
        var net = new NetworkBuilder("Reply sent: receive again", "The last character is out; listen for the next request.")
            .Op("LD", "SM0.0").Op("RCV", c.Layout.B(0), c.PortOperand);
        StopPart.MarkSent(c, net);
        return net.Build();
    }
}
