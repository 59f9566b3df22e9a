using OperatorPanel.Core.Protocol;
using OperatorPanel.StlGen.Model;
using static OperatorPanel.StlGen.Handler.HandlerContext;
using static OperatorPanel.StlGen.Handler.HandlerLayout;
using static OperatorPanel.StlGen.Handler.HandlerSnippets;

namespace OperatorPanel.StlGen.Handler;

/// <summary>
/// 05 DEFINE LIST and 06 READ LIST (docs/protocol-v2.md, "Lists"). Binary payload from buffer byte 8: LIST, then for
/// DEFINE LIST COUNT (9) and the descriptors from byte 10. Stored descriptors stay in the buffer's tail.
/// </summary>
internal static class ListPart
{
    public static IEnumerable<StlNetwork> Define(HandlerContext c)
    {
        var l = c.Layout;
        var e04 = HandlerLabels.Error(ProtocolError.BadLength);
        yield return Label(HandlerLabels.DefineList, "05 DEFINE LIST");
        yield return JumpIf("DEFINE LIST: body at least 5 bytes", $"Error 04 when count < {RequestChars(2)}.", e04, Op("LDB<", l.B(0), RequestChars(2)));
        yield return JumpIf(
            $"DEFINE LIST: COUNT 1-{ProtocolLimits.MaxReadItems}", "Error 04.", e04, Op("LDB=", l.B(9), "0"), Op("OB>", l.B(9), Dec(ProtocolLimits.MaxReadItems)));
        yield return Always(
            "DEFINE LIST: expected length", $"{RequestChars(2)} + 8N characters: AC0 = {RequestChars(2)} + 8N, AC3 = count.",
            Op("BTI", l.B(9), "AC0"), Op("SLW", "AC0", "3"), Op("+I", RequestChars(2), "AC0"), Op("BTI", l.B(0), "AC3"));
        yield return JumpIf("DEFINE LIST: body = 5 + 4 x COUNT bytes", "Error 04.", e04, Op("LDW<>", "AC0", "AC3"));
        yield return JumpIf("DEFINE LIST: LIST 1-4", "Error 06.", HandlerLabels.Error(ProtocolError.BadParameter), Op("LDB=", l.B(8), "0"), Op("OB>", l.B(8), "4"));
        yield return Always(
            "DEFINE LIST: is the list defined?", "LIST and N from the request; AC3 points at LCOUNT of the list.",
            Op("MOVB", l.B(8), l.B(List)), Op("MOVB", l.B(9), l.B(N)), Op("MOVD", l.Ptr(LCount1 - 1), "AC3"),
            Op("BTI", l.B(List), "AC0"), Op("ITD", "AC0", "AC0"), Op("+D", "AC0", "AC3"));
        yield return new NetworkBuilder("DEFINE LIST: redefinition", "A list already defined: forget all lists first.")
            .Op("LDB<>", "*AC3", "0").ClearLists(l).Build();
        yield return Always(
            "DEFINE LIST: room below the floor", "AC0 = 10 + 12N, AC3 = LAST_FREE.",
            Op("BTI", l.B(N), "AC0"), Op("*I", "12", "AC0"), Op("+I", "10", "AC0"), Op("BTI", l.B(LastFree), "AC3"));
        yield return JumpIf("DEFINE LIST: descriptors would overlap their source", "11 + 8N >= F - 4N: error 04.", e04, Op("LDW>=", "AC0", "AC3"));
        yield return PlaceDescriptors(l, 10);
        yield return Always(
            "DEFINE LIST: check the items", "Label 30 checks N items from AC2; the sum of lengths comes back in AC1.",
            Op("MOVB", l.B(N), l.B(I)), Op("MOVD", "0", "AC1"), Op("MOVB", Dec(SlicePart.StepCheckItems), l.B(Step)), Op("JMP", Dec(SlicePart.Yield)));
        foreach (var network in Store(c))
        {
            yield return network;
        }
    }

    public static IEnumerable<StlNetwork> Read(HandlerContext c)
    {
        var l = c.Layout;
        var e07 = HandlerLabels.Error(ProtocolError.ListNotDefined);
        yield return Label(HandlerLabels.ReadList, "06 READ LIST");
        yield return JumpIf(
            "READ LIST: body exactly 4 bytes", $"Error 04 unless count = {RequestChars(1)}.", HandlerLabels.Error(ProtocolError.BadLength), Op("LDB<>", l.B(0), RequestChars(1)));
        yield return JumpIf("READ LIST: LIST 1-4", "Any other LIST is never defined: error 07.", e07, Op("LDB=", l.B(8), "0"), Op("OB>", l.B(8), "4"));
        yield return Always(
            "READ LIST: the list's descriptors", "AC3 points at START of the list, AC2 at its first descriptor; then AC3 at LCOUNT.",
            Op("MOVD", l.Ptr(Start1 - 1), "AC3"), Op("BTI", l.B(8), "AC0"), Op("ITD", "AC0", "AC0"), Op("+D", "AC0", "AC3"),
            Op("MOVD", l.Ptr(0), "AC2"), Op("BTI", "*AC3", "AC0"), Op("ITD", "AC0", "AC0"), Op("+D", "AC0", "AC2"), Op("+D", "4", "AC3"));
        yield return JumpIf("READ LIST: list not defined", "LCOUNT = 0: error 07.", e07, Op("LDB=", "*AC3", "0"));
        yield return Always(
            "READ LIST: build the reply", $"Its items exactly like a READ's, from buffer byte {ReplyPart.PayloadStart}.",
            Op("MOVB", "*AC3", l.B(I)), Op("MOVD", l.Ptr(ReplyPart.PayloadStart), "AC1"), Op("MOVB", Dec(SlicePart.StepBuildItems), l.B(Step)), Op("JMP", Dec(SlicePart.Yield)));
    }

    private static IEnumerable<StlNetwork> Store(HandlerContext c)
    {
        var l = c.Layout;
        yield return Label(HandlerLabels.DefineItemsChecked, "DEFINE LIST items checked");
        yield return Always("DEFINE LIST: largest list reply", "AC0 = D, AC3 = MAXD (the largest D of the stored lists).",
            Op("BTI", l.B(D), "AC0"), Op("BTI", l.B(MaxD), "AC3"));
        yield return new NetworkBuilder("DEFINE LIST: take the larger", "AC0 = larger of D and MAXD.").Op("LDW<", "AC0", "AC3").Op("MOVW", "AC3", "AC0").Build();
        yield return Always(
            "DEFINE LIST: capacity rule",
            $"AC0 = {ListReplyChars} + 2 x largest D, the longest reply of a list (READ CHANGES answering FULL); AC3 = LAST_FREE - 4N, the last byte below the new floor.",
            Op("SLW", "AC0", "1"), Op("+I", ListReplyChars, "AC0"), Op("BTI", l.B(LastFree), "AC3"), Op("BTI", l.B(N), "AC2"),
            Op("SLW", "AC2", "2"), Op("-I", "AC2", "AC3"));
        yield return JumpIf("DEFINE LIST: the lists do not fit together", "A reply would reach the new floor: error 04, nothing stored.",
            HandlerLabels.Error(ProtocolError.BadLength), Op("LDW>", "AC0", "AC3"));
        foreach (var network in c.Options.CopyBytes == 0 ? [] : ChangesPart.Allocate(c))
        {
            yield return network;
        }

        yield return Always(
            "DEFINE LIST: store", "START = LAST_FREE + 1 - 4N, LCOUNT = N, LAST_FREE = START - 1. The descriptors are in place already.",
            Op("MOVD", l.Ptr(Start1 - 1), "AC3"), Op("BTI", l.B(List), "AC0"), Op("ITD", "AC0", "AC0"), Op("+D", "AC0", "AC3"),
            Op("BTI", l.B(LastFree), "AC0"), Op("INCW", "AC0"), Op("BTI", l.B(N), "AC2"), Op("SLW", "AC2", "2"), Op("-I", "AC2", "AC0"),
            Op("MOVB", "AC0", "*AC3"), Op("+D", "4", "AC3"), Op("MOVB", l.B(N), "*AC3"), Op("DECW", "AC0"), Op("MOVB", "AC0", l.B(LastFree)));
        yield return new NetworkBuilder("DEFINE LIST: remember the largest reply", "MAXD = D when D is larger.")
            .Op("LDB>", l.B(D), l.B(MaxD)).Op("MOVB", l.B(D), l.B(MaxD)).Build();
        yield return Always("DEFINE LIST: reply", "STATUS 00, no payload.", Op("MOVB", "0", l.B(List)), Op("MOVD", l.Ptr(ReplyPart.PayloadStart), "AC1"), Op("JMP", Dec(HandlerLabels.Finish)));
    }
}
