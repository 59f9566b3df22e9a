using OperatorPanel.Core.Protocol;
using OperatorPanel.StlGen.Model;
using static OperatorPanel.StlGen.Handler.HandlerContext;
using static OperatorPanel.StlGen.Handler.HandlerLayout;
using static OperatorPanel.StlGen.Handler.HandlerSnippets;

namespace OperatorPanel.StlGen.Handler;

/// <summary>
/// 02 READ (docs/protocol-v2.md sections 2, 4 and 6) and the reply loop READ LIST shares. After the in-place ATH the
/// payload is binary from buffer byte 8: COUNT, then 4 bytes per item from byte 9.
/// </summary>
internal static class ReadPart
{
    /// <summary>Label after the area start of a reply item.</summary>
    private const int BuildAreaFound = 42;

    public static IEnumerable<StlNetwork> Entry(HandlerContext c)
    {
        var l = c.Layout;
        var e04 = HandlerLabels.Error(ProtocolError.BadLength);
        yield return Label(HandlerLabels.Read, "02 READ");
        yield return JumpIf("READ: body at least 4 bytes", $"Error 04 when count < {RequestChars(1)}.", e04, Op("LDB<", l.B(0), RequestChars(1)));
        yield return JumpIf($"READ: COUNT 1-{ProtocolLimits.MaxReadItems}", "Error 04.", e04, Op("LDB=", l.B(8), "0"), Op("OB>", l.B(8), Dec(ProtocolLimits.MaxReadItems)));
        yield return Always(
            "READ: expected length", $"A READ of N items has {RequestChars(1)} + 8N characters: AC0 = {RequestChars(1)} + 8N, AC3 = count.",
            Op("BTI", l.B(8), "AC0"), Op("SLW", "AC0", "3"), Op("+I", RequestChars(1), "AC0"), Op("BTI", l.B(0), "AC3"));
        yield return JumpIf("READ: body = 4 + 4 x COUNT bytes", "Error 04.", e04, Op("LDW<>", "AC0", "AC3"));
        yield return Always(
            "READ: descriptors against the stored lists", "N = COUNT. AC0 = 8 + 12N, AC3 = LAST_FREE.",
            Op("MOVB", l.B(8), l.B(N)), Op("BTI", l.B(N), "AC0"), Op("*I", "12", "AC0"), Op("+I", "8", "AC0"), Op("BTI", l.B(LastFree), "AC3"));
        yield return new NetworkBuilder(
                "READ: descriptors would overlap their source",
                "9 + 8N >= F - 4N (F = LAST_FREE + 1): forget the lists, the descriptors go to the buffer's end.")
            .Op("LDW>=", "AC0", "AC3").ClearLists(l).Build();
        yield return PlaceDescriptors(l, 9);
        yield return Always(
            "READ: check the items", "Label 30 checks N items from AC2; the sum of lengths comes back in AC1.",
            Op("MOVB", l.B(N), l.B(I)), Op("MOVD", "0", "AC1"), Op("MOVB", Dec(SlicePart.StepCheckItems), l.B(Step)), Op("JMP", Dec(SlicePart.Yield)));
    }

    public static IEnumerable<StlNetwork> Reply(HandlerContext c)
    {
        var l = c.Layout;
        yield return Label(HandlerLabels.ReadItemsChecked, "READ items checked");
        yield return Always(
            "READ: reply against the stored lists", $"AC0 = reply length {ReplyChars(0)} + 2D; AC3 = LAST_FREE - 4N, the last byte before the descriptors.",
            Op("BTI", l.B(D), "AC0"), Op("SLW", "AC0", "1"), Op("+I", ReplyChars(0), "AC0"), Op("BTI", l.B(LastFree), "AC3"),
            Op("BTI", l.B(N), "AC2"), Op("SLW", "AC2", "2"), Op("-I", "AC2", "AC3"));
        yield return new NetworkBuilder("READ: reply would reach the descriptors", "Forget the lists (invalidation 3).")
            .Op("LDW>", "AC0", "AC3").ClearLists(l).Build();
        yield return PlaceDescriptors(l, 9);
        yield return Always(
            "READ: build the reply", $"N items from AC2; the data characters start at buffer byte {ReplyPart.PayloadStart} (AC1).",
            Op("MOVB", l.B(N), l.B(I)), Op("MOVD", l.Ptr(ReplyPart.PayloadStart), "AC1"), Op("MOVB", Dec(SlicePart.StepBuildItems), l.B(Step)), Op("JMP", Dec(SlicePart.Yield)));
    }

    /// <summary>In: AC2 at the first descriptor, I = item count, AC1 at the first data character. Out: AC1 after the data.</summary>
    public static IEnumerable<StlNetwork> BuildLoop(HandlerContext c)
    {
        var l = c.Layout;
        foreach (var network in SlicePart.ItemLoop(c, SlicePart.BuildItemsResume, HandlerLabels.BuildItems, SlicePart.ReplyItemsPerScan, "reply data of the next item"))
        {
            yield return network;
        }

        foreach (var network in AreaStart("*AC2", BuildAreaFound))
        {
            yield return network;
        }

        yield return Always(
            "Reply item: data as characters",
            "AC3 = area start + OFFSET; HTA writes 2 x LENGTH characters at AC1; AC1 and AC2 move on; one item fewer.",
            Op("INCD", "AC2"), Op("MOVW", "*AC2", "AC0"), Op("ITD", "AC0", "AC0"), Op("+D", "AC0", "AC3"), Op("INCD", "AC2"),
            Op("INCD", "AC2"), Op("BTI", "*AC2", "AC0"), Op("SLW", "AC0", "1"), Op("HTA", "*AC3", "*AC1", "AC0"),
            Op("ITD", "AC0", "AC0"), Op("+D", "AC0", "AC1"), Op("INCD", "AC2"), Op("DECB", l.B(I)), Op("DECB", l.B(Budget)));
        foreach (var network in SlicePart.ItemLoopEnd(c, SlicePart.BuildItemsResume, HandlerLabels.BuildItems, "Reply item"))
        {
            yield return network;
        }

        yield return Always("Reply items done", "STATUS 00; finish the reply.", Op("MOVB", "0", l.B(List)), Op("JMP", Dec(HandlerLabels.Finish)));
    }
}
