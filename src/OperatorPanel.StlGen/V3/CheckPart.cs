using OperatorPanel.Core.Protocol.V3;
using OperatorPanel.StlGen.Model;
using static OperatorPanel.StlGen.Handler.HandlerSnippets;
using static OperatorPanel.StlGen.V3.Context;

namespace OperatorPanel.StlGen.V3;

/// <summary>
/// The frame check (docs/protocol.md section 1.2) of the request and of the reply, one loop for both: per double word
/// A ^= the double word (folded to 16 bits at the end) and, per 16-bit unit, B = (B ^ unit) * x, a shift left with
/// 16#002D folded back in when SM1.1 says a bit fell out. At most <see cref="PerScan"/> double words per scan (one in the
/// request's first scan), from WALK up to END (the check's place: its bytes are zero while the check is computed, the
/// padding of the last double word). And the reply's head in R, and the send of what is ready.
/// </summary>
internal static class CheckPart
{
    /// <summary>Double words of the check per scan: about 0.49 ms each at the StlTiming figures.</summary>
    public const int PerScan = 2;

    public static IEnumerable<StlNetwork> Networks(Context c)
    {
        var l = c.Layout;
        string a = l.Dw(l.SumA), b = l.W(l.SumB);
        yield return Label(Labels.RequestStart, "phase Start: a request arrived");
        yield return JumpIf(
            "Request: its check",
            "END = the first of its 4 check bytes (byte count - 3): keep them as received, then zero them; A = B = 0; one double word from '<' in this scan (END is 4 on at least).",
            Labels.CheckNext,
            Op("LD", "SM0.0"), Op("MOVD", l.Ptr(-3), "AC1"), Op("BTI", l.B(0), "AC0"), Op("ITD", "AC0", "AC0"), Op("+D", "AC0", "AC1"),
            Op("MOVD", "*AC1", l.Dw(l.Rx)), Op("MOVD", "0", "*AC1"), Op("MOVD", "AC1", l.Dw(l.End)), Op("MOVD", "0", a), Op("MOVW", "0", b),
            l.Go(Phase.Check), Op("MOVD", l.Ptr(1), "AC1"), Op("MOVD", l.Ptr(5), "AC2"));
        yield return Label(Labels.CheckLoop, "phase Check: the frame check");
        yield return Always("Check: this scan", $"AC1 = the next double word, AC2 = {PerScan} double words on.",
            Op("MOVD", l.Dw(l.Walk), "AC1"), Op("MOVD", "AC1", "AC2"), Op("+D", Dec(4 * PerScan), "AC2"));
        yield return new NetworkBuilder("Check: not past END", string.Empty).Op("LDD>", "AC2", l.Dw(l.End)).Op("MOVD", l.Dw(l.End), "AC2").Build();
        yield return Label(Labels.CheckNext, "the next double word");
        yield return Always(
            "Check: one double word", "AC0 = the double word; A ^= it; B ^= its first unit; AC1 on; B * x.",
            Op("MOVD", "*AC1", "AC0"), Op("XORD", "AC0", a), Op("XORW", "*AC1", b), Op("+D", "4", "AC1"), Op("SLW", b, "1"));
        yield return Reduce(b);
        yield return Always("Check: second unit", "B ^= the second unit (AC0's low word), then B * x.", Op("XORW", "AC0", b), Op("SLW", b, "1"));
        yield return Reduce(b);
        yield return JumpIf("Check: more in this scan", string.Empty, Labels.CheckNext, Op("LDD<", "AC1", "AC2"));
        yield return ReturnIf("Check: more in the next scan", "Keep AC1.", Op("LDD<", "AC1", l.Dw(l.End)), Op("MOVD", "AC1", l.Dw(l.Walk)));
        yield return Always("Check: the A field", "Every double word is in: A's low word ^= its high word and B, so the double word from A's low word on is the check (A field, then B).",
            Op("XORW", l.W(l.SumA), l.W(l.SumA + 2)), Op("XORW", b, l.W(l.SumA + 2)));
        if (c.SendsInChunks)
        {
            yield return JumpIf(
                "Check: the reply's", "The reply's check (STEP's reply bit) into its place (END) in one double word; the whole reply is ready (COVERED = END + 3); the request is done.",
                Labels.Publish, Op("LD", l.PhaseBit(Phase.ReplyFlag)), Op("MOVD", l.Dw(l.End), "AC1"), Op("MOVD", l.Dw(l.Check), "*AC1"), Op("+D", "3", "AC1"),
                Op("MOVD", "AC1", l.Dw(l.Covered)), l.Done());
        }
        else
        {
            yield return ReturnIf(
                "Check: the reply's", "The reply's check (STEP's reply bit) into its place (END) in one double word; the whole reply leaves in one XMT from R's count byte (= LEN); the request is done.",
                Op("LD", l.PhaseBit(Phase.ReplyFlag)), Op("MOVD", l.Dw(l.End), "AC1"), Op("MOVD", l.Dw(l.Check), "*AC1"), Op("MOVB", l.B(2), l.B(0)),
                Op("XMT", l.B(0), c.PortOperand), l.Done());
        }

        yield return JumpIf("Request: check differs", "A frame whose check differs gets no reply (its STATION cannot be trusted).", Labels.Silence,
            Op("LDD<>", l.Dw(l.Check), l.Dw(l.Rx)));
        yield return ReturnIf("Request: checked", "The command in the next scan.", Op("LD", "SM0.0"), l.Go(Phase.Dispatch));
    }

    /// <summary>B * x modulo x^16 + x^5 + x^3 + x^2 + 1: the bit SLW shifted out (SM1.1) folds back as 16#002D.</summary>
    private static StlNetwork Reduce(string b) =>
        new NetworkBuilder("Check: reduce", "The bit shifted out of B (SM1.1): XOR x^5 + x^3 + x^2 + 1.")
            .Op("LD", "SM1.1").Op("XORW", Hex(WordCheck.Polynomial), b).Build();

    /// <summary>
    /// Label 2 (a refusal or a reply without payload: P = 0) and phase Reply: LEN, STATUS and REQCHECK (the request's
    /// last check word) after R's '&lt;', the check's place zeroed, head and payload sent at once, the check from the
    /// next scan. In: P in TEMP's first word, the payload from R byte 6; STATUS.
    /// </summary>
    public static IEnumerable<StlNetwork> ReplyHead(Context c)
    {
        var l = c.Layout;
        yield return Label(Labels.ErrorReply, "a reply without payload");
        yield return DispatchPart.ToReply(c, "No payload", "P = 0; the reply next scan.", Op("LD", "SM0.0"), Op("MOVW", "0", l.W(l.Temp)));
        yield return Label(Labels.ReplyInR, "phase Reply: a reply in R");
        if (!c.SendsInChunks)
        {
            yield return ReturnIf(
                "Reply: head",
                "LEN = 9 + P, STATUS, REQCHECK after '<'; END = the check's place, zeroed; the check walks from '<' from the next scan, and the reply leaves whole when it is done.",
                [Op("LD", "SM0.0"), .. Head(l), Op("MOVD", l.Ptr(1), l.Dw(l.Walk)), Op("MOVD", "0", l.Dw(l.SumA)), Op("MOVW", "0", l.W(l.SumB)), l.GoReplyCheck()]);
            yield break;
        }

        yield return Always(
            "Reply: head",
            "LEN = 9 + P, STATUS, REQCHECK after '<'; END = the check's place, zeroed; COVERED its byte before; SENT = the count byte: head and payload leave now, in one chunk (a chunk's count byte overwrites the byte before it, so a second chunk may start only where the check has passed); the check walks from '<' from the next scan.",
            [.. Head(l), Op("MOVD", "AC2", l.Dw(l.Covered)), Op("DECD", l.Dw(l.Covered)),
            Op("MOVD", l.Ptr(0), l.Dw(l.Sent)), Op("MOVD", l.Ptr(1), l.Dw(l.Walk)), Op("MOVD", "0", l.Dw(l.SumA)), Op("MOVW", "0", l.W(l.SumB)),
            l.GoReplyCheck()]);
        yield return new NetworkBuilder(
                "Reply: without payload, whole with its check",
                "9 bytes: nothing ready now (COVERED = SENT), so they leave in one XMT with the check (one transmit interrupt less); the check's first double word in this scan (the head's scan has room, the check's has the XMT).")
            .Op("LDW=", l.W(l.Temp), "0").Op("MOVD", l.Ptr(0), l.Dw(l.Covered)).Op("MOVD", l.Ptr(1), "AC1").Op("MOVD", l.Ptr(5), "AC2").Op("JMP", Dec(Labels.CheckNext)).Build();
        // Then label 98, the send of what is ready, which follows (Builder).
    }

    /// <summary>LEN, STATUS and REQCHECK after '&lt;'; AC2 and END at the check's place (R byte 6 + P), zeroed.</summary>
    private static (string, string[])[] Head(Layout l) =>
    [
        Op("MOVW", l.W(l.Temp), "AC0"), Op("+I", Dec(Limits.ReplyBytes(0)), "AC0"), Op("MOVB", "AC0", l.B(2)), Op("MOVB", l.B(l.Status), l.B(3)), Op("MOVW", l.W(l.Rx + 2), l.W(4)),
        Op("MOVD", l.Ptr(6), "AC2"), Op("ITD", l.W(l.Temp), "AC0"), Op("+D", "AC0", "AC2"), Op("MOVD", "0", "*AC2"), Op("MOVD", "AC2", l.Dw(l.End)),
    ];

    /// <summary>Label 98, OP_PANEL's send: when no chunk is on the wire and bytes are ready, take the transmitter and send them.</summary>
    public static StlNetwork Publish(Context c)
    {
        var l = c.Layout;
        return InterruptPart.Send(c, "Send what is ready", "No chunk on the wire: take the transmitter and send the bytes after SENT up to COVERED.",
                Op("LDN", l.FlagBit(Layout.Owned)), Op("AD>", l.Dw(l.Covered), l.Dw(l.Sent)), Op("S", l.FlagBit(Layout.Owned), "1"))
            .Build();
    }
}
