using OperatorPanel.Core.Protocol;
using OperatorPanel.StlGen.Model;
using static OperatorPanel.StlGen.Handler.HandlerContext;
using static OperatorPanel.StlGen.Handler.HandlerLayout;
using static OperatorPanel.StlGen.Handler.HandlerSnippets;

namespace OperatorPanel.StlGen.Handler;

/// <summary>
/// 03 WRITE and 04 WRITE BIT. Binary payload from buffer byte 8: AREA, OFFSET (9-10), LENGTH or BIT (11), then the
/// data or VALUE (12..). That is a READ descriptor already, so the item checks of label 30 serve both.
/// </summary>
internal static class WritePart
{
    /// <summary>Label after the area start of the written block.</summary>
    private const int WriteAreaFound = 51;

    public static IEnumerable<StlNetwork> Entries(HandlerContext c)
    {
        var l = c.Layout;
        var e04 = HandlerLabels.Error(ProtocolError.BadLength);
        yield return Label(HandlerLabels.Write, "03 WRITE");
        yield return JumpIf("WRITE: body at least 7 bytes", $"Error 04 when count < {RequestChars(4)}.", e04, Op("LDB<", l.B(0), RequestChars(4)));
        yield return JumpIf(
            $"WRITE: LENGTH 1-{ProtocolLimits.MaxWriteData}", "Error 04.", e04, Op("LDB=", l.B(11), "0"), Op("OB>", l.B(11), Dec(ProtocolLimits.MaxWriteData)));
        yield return Always(
            "WRITE: expected length", $"A WRITE of L bytes has {RequestChars(4)} + 2L characters: AC0 = {RequestChars(4)} + 2L, AC3 = count.",
            Op("BTI", l.B(11), "AC0"), Op("SLW", "AC0", "1"), Op("+I", RequestChars(4), "AC0"), Op("BTI", l.B(0), "AC3"));
        yield return JumpIf("WRITE: body = 7 + LENGTH bytes", "Error 04.", e04, Op("LDW<>", "AC0", "AC3"));
        yield return Always(
            "WRITE: check the block", "One item from buffer byte 8 through the item checks of label 30.",
            Op("MOVD", l.Ptr(8), "AC2"), Op("MOVB", "1", l.B(I)), Op("MOVD", "0", "AC1"), Op("MOVB", Dec(SlicePart.StepCheckItems), l.B(Step)), Op("JMP", Dec(SlicePart.Yield)));
        yield return Label(HandlerLabels.WriteBit, "04 WRITE BIT");
        yield return JumpIf("WRITE BIT: body exactly 8 bytes", $"Error 04 unless count = {RequestChars(5)}.", e04, Op("LDB<>", l.B(0), RequestChars(5)));
        yield return Always(
            "WRITE BIT: check the byte", "N = BIT; a LENGTH of 1 in its place makes a one-byte block for the item checks.",
            Op("MOVB", l.B(11), l.B(N)), Op("MOVB", "1", l.B(11)), Op("MOVD", l.Ptr(8), "AC2"), Op("MOVB", "1", l.B(I)),
            Op("MOVD", "0", "AC1"), Op("MOVB", Dec(SlicePart.StepCheckItems), l.B(Step)), Op("JMP", Dec(SlicePart.Yield)));
    }

    public static IEnumerable<StlNetwork> Execute(HandlerContext c)
    {
        var l = c.Layout;
        foreach (var network in Writable(c))
        {
            yield return network;
        }

        foreach (var network in AreaStart(l.B(8), WriteAreaFound))
        {
            yield return network;
        }

        yield return Always("Write: the target byte", "AC3 = area start + OFFSET.", Op("MOVW", l.W(9), "AC0"), Op("ITD", "AC0", "AC0"), Op("+D", "AC0", "AC3"));
        yield return JumpIf("Write: WRITE BIT", "On to label 52.", HandlerLabels.WriteBitExecute, Op("LDB=", l.B(Cmd), Dec(CommandCode.WriteBit)));
        yield return Always(
            "WRITE: copy the data", "BMB the LENGTH data bytes from buffer byte 12 to the target (AC3).",
            Op("BMB", l.B(12), "*AC3", l.B(11)));
        yield return SlicePart.Pause(c, "WRITE: written", SlicePart.StepWriteReadBack);
        yield return Label(SlicePart.WriteReadBack, "WRITE read-back");
        yield return Always(
            "WRITE: read it back", $"HTA the LENGTH bytes at the target back as the reply from buffer byte {ReplyPart.PayloadStart}.",
            Op("BTI", l.B(11), "AC0"), Op("SLW", "AC0", "1"), Op("HTA", "*AC3", l.B(ReplyPart.PayloadStart), "AC0"),
            Op("ITD", "AC0", "AC0"), Op("MOVD", l.Ptr(ReplyPart.PayloadStart), "AC1"), Op("+D", "AC0", "AC1"), Op("MOVB", "0", l.B(List)),
            Op("JMP", Dec(HandlerLabels.Finish)));
        yield return Label(HandlerLabels.WriteBitExecute, "WRITE BIT on the target byte");
        yield return JumpIf("WRITE BIT: BIT 0-7, VALUE 0-1", "Error 06.", HandlerLabels.Error(ProtocolError.BadParameter), Op("LDB>", l.B(N), "7"), Op("OB>", l.B(12), "1"));
        yield return Always("WRITE BIT: bit mask", "D = 1 shifted left by BIT.", Op("MOVB", "1", l.B(D)), Op("SLB", l.B(D), l.B(N)));
        yield return new NetworkBuilder("WRITE BIT: set", "VALUE 1: OR the mask into the byte; the other bits stay.")
            .Op("LDB=", l.B(12), "1").Op("ORB", l.B(D), "*AC3").Build();
        yield return new NetworkBuilder("WRITE BIT: reset", "VALUE 0: AND the inverted mask into the byte; the other bits stay.")
            .Op("LDB=", l.B(12), "0").Op("INVB", l.B(D)).Op("ANDB", l.B(D), "*AC3").Build();
        yield return Always(
            "WRITE BIT: read back", $"The whole byte as 2 characters from buffer byte {ReplyPart.PayloadStart}.",
            Op("HTA", "*AC3", l.B(ReplyPart.PayloadStart), "2"), Op("MOVD", l.Ptr(ReplyPart.PayloadStart + 2), "AC1"), Op("MOVB", "0", l.B(List)), Op("JMP", Dec(HandlerLabels.Finish)));
    }

    /// <summary>
    /// Error 03: I; areas outside the write mask; the handler's own V bytes (a WRITE there could make the read-back
    /// run past the buffer, and the CPU stop); SM bytes the panel must not touch (docs/protocol-v2.md section 3).
    /// </summary>
    private static IEnumerable<StlNetwork> Writable(HandlerContext c)
    {
        var l = c.Layout;
        var e03 = HandlerLabels.Error(ProtocolError.NotWritable);
        yield return Label(HandlerLabels.Writable, "may the panel write here?");
        yield return JumpIf("Writable: never I", "Error 03.", e03, Op("LDB=", l.B(8), "1"));
        foreach (var (code, name) in new[] { (2, "Q"), (3, "M"), (4, "V"), (5, "SM") }.Where(a => !c.MayWrite(a.Item1)))
        {
            yield return JumpIf($"Writable: not {name}", $"{name} is not in the write mask: error 03.", e03, Op("LDB=", l.B(8), Dec(code)));
        }

        if (!c.MayWrite(4) && !c.MayWrite(5))
        {
            yield break;
        }

        yield return Always("Writable: first and last byte", "AC0 = OFFSET, AC3 = OFFSET + LENGTH - 1.",
            Op("MOVW", l.W(9), "AC0"), Op("BTI", l.B(11), "AC3"), Op("+I", "AC0", "AC3"), Op("DECW", "AC3"));
        if (c.MayWrite(4))
        {
            yield return JumpIf(
                $"Writable: not the handler's own bytes", $"VB{l.BufferStart}-VB{l.LastByte}, buffer and work bytes: a block touching them is refused whole, error 03.",
                e03, Op("LDB=", l.B(8), "4"), Op("AW<=", "AC0", Dec(l.LastByte)), Op("AW>=", "AC3", Dec(l.BufferStart)));
        }

        if (!c.MayWrite(5))
        {
            yield break;
        }

        var readOnly = c.Options.Cpu.ReadOnlySmBytes;
        yield return JumpIf($"Writable: SMB0-SMB{readOnly - 1}", "System status bytes: error 03.", e03, Op("LDB=", l.B(8), "5"), Op("AW<", "AC0", Dec(readOnly)));
        foreach (var (first, last, what) in new[]
        {
            (34, 34, "SMB34, the reply delay"), (c.SmPort(30), c.SmPort(30), $"{c.SmB(30)}, the port mode"),
            (c.SmPort(86), c.SmPort(94), $"{c.SmB(86)}-{c.SmB(94)}, the receive set-up"),
        })
        {
            yield return JumpIf($"Writable: {what}", "A block touching it is refused whole: error 03.", e03,
                Op("LDB=", l.B(8), "5"), Op("AW<=", "AC0", Dec(last)), Op("AW>=", "AC3", Dec(first)));
        }
    }
}
