using OperatorPanel.StlGen.Model;
using static OperatorPanel.StlGen.Handler.HandlerSnippets;
using static OperatorPanel.StlGen.V3.Context;

namespace OperatorPanel.StlGen.V3;

/// <summary>
/// The two interrupt routines. The receive routine only takes a message of LEN bytes for this station. The compact
/// handler's reply leaves whole (<see cref="Context.SendsInChunks"/>): its transmit routine only receives again. The full
/// handler's reply leaves in chunks: OP_PANEL moves COVERED to the last byte ready; when the transmitter is free it takes it (FLAGS
/// bit 0) and sends COVERED - SENT bytes with XMT from the byte at SENT (the count byte, then the last byte already
/// sent); at the chunk's transmit complete the routine below sends what became ready meanwhile, or frees the
/// transmitter. It is free only when no XMT is running, so no interrupt can act between OP_PANEL's test and its XMT
/// (docs/protocol.md section 6).
/// </summary>
internal static class InterruptPart
{
    public static IEnumerable<StlNetwork> Receive(Context c)
    {
        var l = c.Layout;
        yield return new NetworkBuilder(
                "Not a request for this station: receive again",
                $"Count (byte 0) not LEN (byte 2), LEN below 8, or STATION (byte 3) not {c.Options.Station}: another station's frame, a reply, noise.")
            .Op("LDB=", l.B(0), l.B(2)).Op("AB>=", l.B(2), "8").Op("AB=", l.B(3), Dec(c.Options.Station)).Op("NOT")
            .Op("RCV", l.B(0), c.PortOperand).Op("CRETI").Build();
        yield return Always("A request is waiting", $"{c.Names.Panel} checks and answers it, a bounded part per scan (phase Start).", l.Go(Phase.Start));
    }

    /// <summary>
    /// The most frequent case first (bytes ready: the next chunk), so a chunk's routine is the shortest; then the
    /// transmitter is released, and when the request is done (STEP 0, everything sent) the reply to STOP sets STOP
    /// now, any other receives the next request.
    /// </summary>
    public static IEnumerable<StlNetwork> Transmit(Context c)
    {
        var l = c.Layout;
        if (!c.SendsInChunks)
        {
            yield return Always("The reply is out", "It left whole in one XMT: receive the next request.", Op("RCV", l.B(0), c.PortOperand));
            yield break;
        }

        yield return Send(c, "The next chunk", "Bytes ready since the last chunk: send them, keep the transmitter.", Op("LDD>", l.Dw(l.Covered), l.Dw(l.Sent)))
            .Op("CRETI").Build();
        yield return Always("Nothing ready", $"Release the transmitter: {c.Names.Panel} sends the next chunk when it is ready.", Op("R", l.FlagBit(Layout.Owned), "1"));
        if (c.HasStop)
        {
            yield return new NetworkBuilder("The reply to STOP is out", $"{c.Names.Panel} executes STOP in its next scan; no receive.")
                .Op("LDW=", l.W(l.Step), "0").Op("AD=", l.Dw(l.Sent), l.Dw(l.Covered)).Op("AB=", l.B(l.Cmd), Dec(Core.Protocol.V3.Command.Stop)).Op("AB=", l.B(l.Status), Hex(Core.Protocol.V3.ReplyStatus.Ok))
                .Op("S", l.FlagBit(Layout.StopNow), "1").Op("CRETI").Build();
        }

        yield return new NetworkBuilder("The whole reply is out", "Everything ready is sent and the request is done (its check too): receive the next request.")
            .Op("LDW=", l.W(l.Step), "0").Op("AD=", l.Dw(l.Sent), l.Dw(l.Covered)).Op("RCV", l.B(0), c.PortOperand).Build();
    }

    /// <summary>
    /// After <paramref name="condition"/>: XMT the bytes after SENT up to COVERED, from the byte at SENT, which takes
    /// their count (docs/sources/s7200-facts.md section 8: XMT's table through *VD or *AC; here *AC1, read by nothing
    /// after the XMT), and SENT = COVERED before the XMT: a user's interrupt routine may run between OP_PANEL's XMT and
    /// its next instruction for longer than the chunk takes on the wire (facts section 5: an interrupt comes "at any
    /// point", none pre-empts another), and OP_TX, served after it, must find SENT moved on, or it sends the chunk again.
    /// </summary>
    public static NetworkBuilder Send(Context c, string title, string comment, params (string, string[])[] condition)
    {
        var l = c.Layout;
        var net = new NetworkBuilder(title, comment);
        foreach (var (mnemonic, operands) in condition)
        {
            net.Op(mnemonic, operands);
        }

        return net.Op("MOVD", l.Dw(l.Covered), "AC0").Op("-D", l.Dw(l.Sent), "AC0").Op("MOVB", "AC0", "*" + l.Dw(l.Sent))
            .Op("MOVD", l.Dw(l.Sent), "AC1").Op("MOVD", l.Dw(l.Covered), l.Dw(l.Sent)).Op("XMT", "*AC1", c.PortOperand);
    }
}
