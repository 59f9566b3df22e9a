using OperatorPanel.Core.Protocol.V3;
using OperatorPanel.StlGen.Model;
using static OperatorPanel.StlGen.Handler.HandlerSnippets;
using static OperatorPanel.StlGen.V3.Context;

namespace OperatorPanel.StlGen.V3;

/// <summary>
/// 05 DEFINE LIST (docs/protocol.md section 2): N items of 4 bytes from byte 5 (AREA, OFFSET, LENGTH 1-4), N a whole
/// number of groups of 8 up to LIST_ITEMS. The old list is gone at once (N = 0). Each item is checked like a READ of 4
/// bytes (its slot's window must lie in the area) and stored as a slot (destination in R, where the previous item's
/// bytes end; source; length), in two scans (phases DefineSlot, DefineStore). The first failing item ends the request
/// with its status and leaves no list. After the last: N, D and the groups in use.
/// </summary>
internal static class DefinePart
{
    public static IEnumerable<StlNetwork> Networks(Context c)
    {
        var l = c.Layout;
        var lenWord = ItemPart.LengthWord(l);
        var groupBytes = 4 * HandlerShape.GroupSlots;
        yield return Label(Labels.DefineList, "05 DEFINE LIST");
        yield return Always("DEFINE LIST: the old list is gone", $"N = 0, the copy not valid, whatever follows. P = count - 8 in TEMP; AC0 = P MOD {groupBytes}.",
            Op("MOVB", "0", l.B(l.N)), Op("R", l.FlagBit(Layout.CopyValid), "1"), Op("BTI", l.B(0), l.W(l.Temp)), Op("-I", Dec(Limits.RequestBytes(0)), l.W(l.Temp)), Op("MOVW", l.W(l.Temp), "AC0"),
            Op("ANDW", Dec(groupBytes - 1), "AC0"));
        yield return Refusal.If(l, "DEFINE LIST: whole groups", $"P 0 or not a multiple of {groupBytes}: 84 (P <= 4 x LIST_ITEMS as MAX_REQUEST = 4 x LIST_ITEMS + 8).",
            ReplyStatus.BadLength, Op("LDW=", l.W(l.Temp), "0"), Op("OW<>", "AC0", "0"));
        yield return ReturnIf(
            "DEFINE LIST: from slot 0",
            "Slots from slot 0, data from R byte 6 (TAIL); items from byte 5 (WALK) to byte 5 + P (END), one per two scans; the item check for a 4-byte window.",
            Op("LD", "SM0.0"), Op("MOVD", l.Ptr(l.Slots), l.Dw(l.NextSlot)), Op("MOVD", l.Ptr(6), l.Dw(l.Tail)), Op("MOVD", l.Ptr(5), l.Dw(l.Walk)),
            Op("ITD", l.W(l.Temp), "AC0"), Op("MOVD", l.Ptr(5), l.Dw(l.End)), Op("+D", "AC0", l.Dw(l.End)), Op("MOVW", Dec(HandlerShape.ItemBytes), lenWord), l.Go(Phase.DefineSlot));
        yield return Label(Labels.DefineItem, "phase DefineSlot: the next item");
        yield return Always("DEFINE LIST: the item", "AC2 = its AREA; its LENGTH (fourth byte) kept in COUNT till its slot is stored.",
            Op("MOVD", l.Dw(l.Walk), "AC2"), Op("MOVD", "AC2", "AC1"), Op("+D", "3", "AC1"), Op("MOVB", "*AC1", l.B(l.Count)));
        yield return Refusal.If(l, "DEFINE LIST: LENGTH 1 to 4", "84.", ReplyStatus.BadLength, Op("LDB=", l.B(l.Count), "0"), Op("OB>", l.B(l.Count), Dec(HandlerShape.ItemBytes)));
        yield return JumpIf("DEFINE LIST: check the item", "Through label 20, which leaves its first byte in LAST (free till the reply) and goes on in phase DefineStore.", Labels.ItemCheck, Op("LD", "SM0.0"));
        yield return Label(Labels.DefineStore, "phase DefineStore: the slot");
        yield return Always(
            "DEFINE LIST: store the slot", "Destination (TAIL), source (LAST), length; TAIL on by the length; the next slot and item.",
            Op("MOVD", l.Dw(l.NextSlot), "AC1"), Op("MOVD", l.Dw(l.Tail), "*AC1"), Op("+D", "4", "AC1"), Op("MOVD", l.Dw(l.Last), "*AC1"), Op("+D", "4", "AC1"),
            Op("MOVB", l.B(l.Count), "*AC1"), Op("INCD", "AC1"), Op("MOVD", "AC1", l.Dw(l.NextSlot)), Op("BTI", l.B(l.Count), "AC0"), Op("ITD", "AC0", "AC0"), Op("+D", "AC0", l.Dw(l.Tail)),
            Op("+D", "4", l.Dw(l.Walk)));
        yield return ReturnIf("DEFINE LIST: more items", "The next one in the next scan.", Op("LDD<", l.Dw(l.Walk), l.Dw(l.End)), l.Go(Phase.DefineSlot));
        yield return JumpIf(
            "DEFINE LIST: done",
            "N = P / 4; USED = 2 ^ (N / 8) - 1 (a bit per group); D = TAIL - R byte 6. Reply 80, no payload.",
            Labels.ErrorReply, Op("LD", "SM0.0"), Op("MOVW", l.W(l.Temp), "AC0"), Op("SRW", "AC0", "2"), Op("MOVB", "AC0", l.B(l.N)),
            Op("SRW", "AC0", "3"), Op("MOVB", "1", l.B(l.Used)), Op("SLB", l.B(l.Used), "AC0"), Op("DECB", l.B(l.Used)), Op("MOVD", l.Dw(l.Tail), "AC0"), Op("MOVD", l.Ptr(6), "AC1"), Op("-D", "AC1", "AC0"),
            Op("MOVB", "AC0", l.B(l.D)));
    }
}
