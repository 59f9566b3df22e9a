using OperatorPanel.StlGen.Model;
using static OperatorPanel.StlGen.Handler.HandlerContext;

namespace OperatorPanel.StlGen.Handler;

/// <summary>
/// OB1's call and the handler's subroutine: Freeport while the mode switch is at RUN, PPI at TERM so Micro/WIN can
/// connect (seed 002 Table C-1, SM0.7), set up again on the first scan and on every change of SM0.7.
/// </summary>
internal static class InitPart
{
    public static StlNetwork MainCall(HandlerContext c) =>
        new NetworkBuilder(
                "Operator panel: call the port handler every scan",
                $"{c.Names.Panel} sets port {c.Port} to Freeport at RUN and gives it back to PPI at TERM.",
                "It also serves the requests, a bounded part per scan: keep this call in every scan.")
            .Op("LD", "SM0.0").Op("CALL", c.Names.Panel).Build();

    public static IEnumerable<StlNetwork> Subroutine(HandlerContext c)
    {
        var l = c.Layout;
        var freeport = new NetworkBuilder(
                "Freeport on: first scan at RUN, or switch turned to RUN",
                $"{c.SmB(30)} = {Hex(c.FreeportControl)}: Freeport, {c.Options.BaudRate} baud, {c.Options.DataBits} data bits, parity {c.Options.Parity.ToString().ToLowerInvariant()}.",
                $"Receive: start '<' ({c.SmB(88)}), end '>' ({c.SmB(89)}), at most 255 characters ({c.SmB(94)}).",
                c.Options.CharTimeoutMs == 0
                    ? $"{c.SmB(87)} = 16#E0: no idle line, no timer."
                    : $"{c.SmB(87)} = 16#E4: a frame cut off ends after {c.Options.CharTimeoutMs} ms without a character ({c.SmW(92)}).",
                $"Clear the READ lists, attach {c.Names.Receive} (event {c.ReceiveEvent}) and {c.Names.Transmit} (event {c.TransmitEvent}), enable interrupts, no request waiting, start receiving.")
            .Op("LD", "SM0.7").Op("AN", RunSeen(c)).Op("LD", "SM0.1").Op("A", "SM0.7").Op("OLD")
            .Op("MOVB", Hex(c.FreeportControl), c.SmB(30))
            .Op("MOVB", c.Options.CharTimeoutMs == 0 ? "16#E0" : "16#E4", c.SmB(87))
            .Op("MOVB", "16#3C", c.SmB(88)).Op("MOVB", "16#3E", c.SmB(89)).Op("MOVW", "0", c.SmW(90));
        if (c.Options.CharTimeoutMs != 0)
        {
            freeport.Op("MOVW", Dec(c.Options.CharTimeoutMs), c.SmW(92));
        }

        freeport.Op("MOVB", "255", c.SmB(94)).ClearLists(l).Forget(c).Op("DTCH", Dec(DelayEvent))
            .Op("ATCH", c.Names.Receive, Dec(c.ReceiveEvent)).Op("ATCH", c.Names.Transmit, Dec(c.TransmitEvent))
            .Op("ENI").Op("MOVB", "0", l.B(HandlerLayout.Step)).Op("RCV", l.B(0), c.PortOperand);
        yield return freeport.Build();

        yield return new NetworkBuilder(
                "PPI again: first scan at TERM, or switch turned to TERM",
                $"{c.SmB(30)} = 0 gives port {c.Port} back to PPI, so a programming device can connect without stopping the CPU.",
                $"Detach the handler's events {c.ReceiveEvent}, {c.TransmitEvent} and {DelayEvent}; a request being served and the READ lists are forgotten.")
            .Op("LDN", "SM0.7").Op("A", RunSeen(c)).Op("LD", "SM0.1").Op("AN", "SM0.7").Op("OLD")
            .Op("MOVB", "0", c.SmB(30)).Op("DTCH", Dec(c.ReceiveEvent)).Op("DTCH", Dec(c.TransmitEvent))
            .Op("DTCH", Dec(DelayEvent)).Op("MOVB", "0", l.B(HandlerLayout.Step)).ClearLists(l).Forget(c).Build();

        yield return new NetworkBuilder(
                "Mode switch as this scan saw it",
                $"OP_STOP bit {HandlerLayout.RunSeenBit} = SM0.7, for the edges above in the next scan: a contact takes 0.37 us (System Manual",
                "C233-01 Table A-2, Boolean); EU and ED have no published time and count as 46 us each, in every scan.")
            .Op("LD", "SM0.7").Op("=", RunSeen(c)).Build();
    }

    /// <summary>The bit that keeps SM0.7 from the last scan.</summary>
    private static string RunSeen(HandlerContext c) => c.Layout.Bit(HandlerLayout.StopState, HandlerLayout.RunSeenBit);
}
