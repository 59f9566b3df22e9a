using OperatorPanel.Core.Protocol;
using OperatorPanel.StlGen.Model;
using static OperatorPanel.StlGen.Handler.HandlerContext;
using static OperatorPanel.StlGen.Handler.HandlerLayout;
using static OperatorPanel.StlGen.Handler.HandlerSnippets;

namespace OperatorPanel.StlGen.Handler;

/// <summary>
/// 07 STOP, only in a handler generated with <see cref="Options.HandlerOptions.AllowStop"/>: the reply first, then the
/// STOP instruction from OP_PANEL (called from OB1), never from an interrupt routine: the Micro/WIN help on WDR lists
/// "STOP instruction, when used in an interrupt routine" among what waits for the end of the scan, and the System Manual
/// (A5E00307987-04, STOP instruction) ends the interrupt routine at once and makes the transition at the end of the
/// scan. OP_STOP bit 0 = the STOP reply is built; the transmit-complete routine copies it to bit 1 when the reply is
/// out; OP_PANEL executes STOP in the next scan. In STOP the CPU gives the port back to PPI by itself.
/// </summary>
internal static class StopPart
{
    /// <summary>The payload "STOP" as one double word (53 54 4F 50).</summary>
    private const string StopWord = "16#53544F50";

    /// <summary>The network at the top of OP_PANEL: the STOP reply went out, so stop now.</summary>
    public static IEnumerable<StlNetwork> Execute(HandlerContext c)
    {
        if (!c.Options.AllowStop)
        {
            yield break;
        }

        var l = c.Layout;
        yield return new NetworkBuilder(
                "STOP reply sent: CPU to STOP",
                "OP_STOP bit 1: the panel's STOP request was answered and its reply has left; STOP ends this scan in STOP mode.")
            .Op("LD", l.Bit(StopState, 1)).Op("STOP").Build();
    }

    /// <summary>07 STOP: body exactly 7 bytes (04), payload "STOP" (06); reply STATUS 00 without payload.</summary>
    public static IEnumerable<StlNetwork> Networks(HandlerContext c)
    {
        if (!c.Options.AllowStop)
        {
            yield break;
        }

        var l = c.Layout;
        yield return Label(HandlerLabels.Stop, "07 STOP");
        yield return JumpIf("STOP: body exactly 7 bytes", $"Error 04 unless count = {RequestChars(4)}.",
            HandlerLabels.Error(ProtocolError.BadLength), Op("LDB<>", l.B(0), RequestChars(4)));
        yield return JumpIf("STOP: payload 'STOP'", "Bytes 53 54 4F 50, else error 06.", HandlerLabels.Error(ProtocolError.BadParameter),
            Op("LDD<>", l.Dw(8), StopWord));
        yield return Always(
            "STOP: reply, then STOP", "OP_STOP bit 0: the transmit-complete routine marks the reply sent; STATUS 00, no payload.",
            Op("ORB", "16#01", l.B(StopState)), Op("MOVD", l.Ptr(ReplyPart.PayloadStart), "AC1"), Op("MOVB", "0", l.B(List)), Op("JMP", Dec(HandlerLabels.Finish)));
    }

    /// <summary>In the transmit-complete routine: the reply that left was the STOP reply (bit 0) -> sent (bit 1).</summary>
    public static void MarkSent(HandlerContext c, NetworkBuilder transmit)
    {
        ArgumentNullException.ThrowIfNull(transmit);
        if (c.Options.AllowStop)
        {
            transmit.Op("LD", c.Layout.Bit(StopState, 0)).Op("=", c.Layout.Bit(StopState, 1));
        }
    }

    /// <summary>Port set up or given back (RUN, TERM, first scan): no STOP reply is on its way.</summary>
    public static NetworkBuilder Forget(this NetworkBuilder net, HandlerContext c) =>
        c.Options.AllowStop ? net.Op("MOVB", "0", c.Layout.B(StopState)) : net;
}
