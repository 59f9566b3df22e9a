using OperatorPanel.StlGen.Model;
using static OperatorPanel.StlGen.Handler.HandlerContext;
using static OperatorPanel.StlGen.Handler.HandlerLayout;
using static OperatorPanel.StlGen.Handler.HandlerSnippets;

namespace OperatorPanel.StlGen.Handler;

/// <summary>
/// The reply leaves in chunks while OP_PANEL still computes its check (docs/protocol-v2.md section 6, steps 6 and 7): the
/// characters a pass of the check has covered are final. After every pass OP_PANEL publishes COVERED in one MOVD, and
/// only then reads OP_STOP bit 2 (<see cref="SendingBit"/>). The first pass attaches the reply delay, whose routine
/// sends buffer bytes 1 .. COVERED (byte 0, the first SENT, takes the count); every later chunk's XMT table is SENT,
/// the previous chunk's last character, already on the wire once its transmit complete came. Characters are sent by
/// whoever finds them covered and nothing pending: the transmit-complete routine after each chunk, or OP_PANEL after
/// a pass when bit 2 is clear. Interrupt routines never nest and run only between two instructions of OP_PANEL
/// (docs/sources/s7200-facts.md section 5), so a transmit complete before the publish leaves bit 2 clear and OP_PANEL
/// sends the new characters; one after the publish sends them itself and leaves bit 2 set, so OP_PANEL does not; and
/// with bit 2 clear no chunk and no delay is pending, so nothing of ours can interrupt OP_PANEL's own send.
/// </summary>
internal static class ChunkPart
{
    /// <summary>Label after a pass of the reply's check: COVERED is AC2, the last character it covered.</summary>
    public const int PassCovered = 80;

    /// <summary>The end of every pass of the reply's check, at <see cref="PassCovered"/>; AC3 = pairs left (0: the '&gt;' is covered).</summary>
    public static IEnumerable<StlNetwork> AfterPass(HandlerContext c)
    {
        var l = c.Layout;
        var first = Dec(SlicePart.StepReplyCheck);
        var sending = l.Bit(StopState, SendingBit);
        yield return Label(PassCovered, "a pass of the reply's check done");
        yield return Always(
            "Reply: publish what the check covers",
            "COVERED = AC2 in one instruction, before bit 2 is read: a transmit complete falling here or later sends these characters itself.",
            Op("MOVD", "AC2", l.Dw(Covered)));
        yield return new NetworkBuilder(
                "Reply: first pass, the reply delay",
                $"STEP is still {first} in the reply check's first scan. Bit 2: the delay is pending. Timed interrupt 0 sends the first",
                $"chunk in {c.Options.ReplyDelayMs} ms (SMB34), as much as the check has covered by then.")
            .Op("LDB=", l.B(Step), first).Op("S", sending, "1").Op("MOVB", Dec(c.Options.ReplyDelayMs), "SMB34")
            .Op("ATCH", c.Names.Delay, Dec(DelayEvent)).Build();
        yield return new NetworkBuilder(
                "Reply: a later pass, transmitter waiting",
                "Bit 2 clear: the last chunk is out and nothing is pending, so no routine of ours runs before this XMT. SENT moves on",
                "and bit 2 is set before the XMT, whose transmit complete may come at once. AC1 = the table, AC0 = the count.")
            .Op("LDB<>", l.B(Step), first).Op("AN", sending).Op("MOVD", l.Dw(Sent), "AC1").Op("MOVD", l.Dw(Covered), "AC0")
            .Op("-D", "AC1", "AC0").Op("MOVB", "AC0", "*AC1").Op("MOVD", l.Dw(Covered), l.Dw(Sent)).Op("S", sending, "1")
            .Op("XMT", "*AC1", c.PortOperand).Build();
        yield return JumpIf(
            "Reply: pairs left", $"The next scan goes on with another pass (STEP {SlicePart.StepReplyCheckPass}); SAVE keeps AC2 and AC3 only.",
            SlicePart.KeepWalkers, Op("LDW>", "AC3", "0"), Op("MOVB", Dec(SlicePart.StepReplyCheckPass), l.B(Step)));
        yield return Always(
            "Reply: check done", "The rest of the reply leaves from the transmit-complete routine; nothing left for the next scans.",
            SlicePart.Done(c), Op("JMP", Dec(SlicePart.EndOfSlice)));
    }

    /// <summary>
    /// The send of the reply delay and the transmit-complete routine: the COVERED - SENT characters after SENT, with
    /// SENT's byte as the XMT table holding their count; SENT = COVERED.
    /// </summary>
    public static NetworkBuilder SendCovered(this NetworkBuilder net, HandlerContext c)
    {
        ArgumentNullException.ThrowIfNull(net);
        var l = c.Layout;
        return net.Op("MOVD", l.Dw(Covered), "AC0").Op("-D", l.Dw(Sent), "AC0").Op("MOVB", "AC0", "*" + l.Dw(Sent))
            .Op("XMT", "*" + l.Dw(Sent), c.PortOperand).Op("MOVD", l.Dw(Covered), l.Dw(Sent));
    }
}
