using OperatorPanel.StlGen.Model;
using static OperatorPanel.StlGen.V3.Context;

namespace OperatorPanel.StlGen.V3;

/// <summary>
/// OB1's call, and the port's set-up in OP_PANEL: Freeport while the mode switch is at RUN, PPI at TERM (seed 002
/// Table C-1, SM0.7), set up again on the first scan and on every change of SM0.7. The receive set-up is docs/protocol.md
/// section 1.5's: start character '&lt;', end after SMW92 ms without a character or SMB94 characters.
/// </summary>
internal static class PortPart
{
    /// <summary>SMB87: en (receive enabled), sc (start character), tmr (end by the timer, an inter-character timer).</summary>
    public const int ReceiveControl = 0xC4;

    public static StlNetwork MainCall(Context c) =>
        new NetworkBuilder(
                "Operator panel: call the port handler every scan",
                $"{c.Names.Panel} sets port {c.Port} to Freeport at RUN and gives it back to PPI at TERM; it also serves the",
                "requests, a bounded part per scan: keep this call in every scan.")
            .Op("LD", "SM0.0").Op("CALL", c.Names.Panel).Build();

    public static IEnumerable<StlNetwork> Networks(Context c)
    {
        var l = c.Layout;
        var on = new NetworkBuilder(
                "Freeport on: first scan at RUN, or switch turned to RUN",
                $"{c.SmB(30)} = {Hex(c.FreeportControl)}: Freeport, {c.Options.BaudRate} baud, {c.Options.DataBits} data bits, parity {c.Options.Parity.ToString().ToLowerInvariant()}.",
                $"{c.SmB(87)} = {Hex(ReceiveControl)}: start '<' ({c.SmB(88)}), end {c.EndTimeoutMs} ms after the last character ({c.SmW(92)}) or after {c.Shape.RequestBytes} ({c.SmB(94)}).",
                $"The end timeout is also the reply's earliest start (the converter's turnaround). No request, list forgotten; attach {c.Names.Receive} and {c.Names.Transmit}, receive.")
            .Op("LD", "SM0.7").Op("AN", l.FlagBit(Layout.RunSeen)).Op("LD", "SM0.1").Op("A", "SM0.7").Op("OLD")
            .Op("MOVB", Hex(c.FreeportControl), c.SmB(30)).Op("MOVB", Hex(ReceiveControl), c.SmB(87)).Op("MOVB", "16#3C", c.SmB(88))
            .Op("MOVW", Dec(c.EndTimeoutMs), c.SmW(92)).Op("MOVB", Dec(c.Shape.RequestBytes), c.SmB(94))
            .Ops([l.Done()]);
        if (c.HasList)
        {
            // FLAGS but SM0.7's bit: a chunk's transmitter, STOP now, the copy's bits (the compact handler has none of them).
            on.Op("ANDB", Hex(1 << Layout.RunSeen), l.B(l.Flags)).Op("MOVB", "0", l.B(l.N));
        }

        yield return on.Op("ATCH", c.Names.Receive, Dec(c.ReceiveEvent)).Op("ATCH", c.Names.Transmit, Dec(c.TransmitEvent))
            .Op("ENI").Op("RCV", l.B(0), c.PortOperand).Build();
        var off = new NetworkBuilder(
                "PPI again: first scan at TERM, or switch turned to TERM",
                $"{c.SmB(30)} = 0 gives port {c.Port} back to PPI, so a programming device can connect without stopping the CPU.",
                "A request being served and the list are forgotten (the events stay attached: in PPI no Freeport event comes).")
            .Op("LDN", "SM0.7").Op("A", l.FlagBit(Layout.RunSeen)).Op("LD", "SM0.1").Op("AN", "SM0.7").Op("OLD")
            .Op("MOVB", "0", c.SmB(30)).Ops([l.Done()]);
        if (c.HasList)
        {
            off.Op("ANDB", Hex(1 << Layout.RunSeen), l.B(l.Flags)).Op("MOVB", "0", l.B(l.N));
        }

        yield return off.Build();
        yield return new NetworkBuilder(
                "Mode switch as this scan saw it",
                $"FLAGS bit {Layout.RunSeen} = SM0.7 for the edges above in the next scan (a contact takes 0.37 us; EU/ED have no published time).")
            .Op("LD", "SM0.7").Op("=", l.FlagBit(Layout.RunSeen)).Build();
        if (c.HasStop)
        {
            yield return new NetworkBuilder(
                    "STOP after its reply",
                    $"{c.Names.Transmit} set FLAGS bit {Layout.StopNow} when the reply to 08 STOP had left: the CPU goes to STOP (in the",
                    "subroutine, not in the interrupt routine: docs/protocol.md, 08 STOP).")
                .Op("LD", l.FlagBit(Layout.StopNow)).Op("STOP").Build();
        }
    }
}
