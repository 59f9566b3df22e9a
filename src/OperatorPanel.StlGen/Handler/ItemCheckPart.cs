using OperatorPanel.Core.Protocol;
using OperatorPanel.StlGen.Model;
using static OperatorPanel.StlGen.Handler.HandlerContext;
using static OperatorPanel.StlGen.Handler.HandlerLayout;
using static OperatorPanel.StlGen.Handler.HandlerSnippets;

namespace OperatorPanel.StlGen.Handler;

/// <summary>
/// The item checks shared by READ, DEFINE LIST, WRITE and WRITE BIT (docs/protocol-v2.md section 4, step 6): per item
/// LENGTH 0 -> 04, unknown area -> 02, OFFSET + LENGTH past the area -> 02, the first failing item decides. In: AC2 at
/// the first 4-byte descriptor (AREA, OFFSET high, OFFSET low, LENGTH), I = item count, AC1 = 0. Out: AC1 = sum of
/// the lengths; then READ and DEFINE LIST check 2D + 4N &lt;= 237 (a reply of 18 + 2D characters ends before the
/// descriptors at 256 - 4N), WRITE and WRITE BIT go on to the write checks.
/// </summary>
internal static class ItemCheckPart
{
    public static IEnumerable<StlNetwork> Networks(HandlerContext c)
    {
        var l = c.Layout;
        var e02 = HandlerLabels.Error(ProtocolError.AddressOutOfRange);
        var e04 = HandlerLabels.Error(ProtocolError.BadLength);
        foreach (var network in SlicePart.ItemLoop(c, SlicePart.CheckItemsResume, HandlerLabels.CheckItems, SlicePart.ItemsPerScan, "check the next item"))
        {
            yield return network;
        }

        yield return Always("Item: where its LENGTH is", "AC3 points at LENGTH, 3 bytes after AREA.", Op("MOVD", "AC2", "AC3"), Op("+D", "3", "AC3"));
        yield return JumpIf("Item: LENGTH 0", "Error 04.", e04, Op("LDB=", "*AC3", "0"));
        yield return JumpIf("Item: unknown area", "AREA not 1-5: error 02.", e02, Op("LDB=", "*AC2", "0"), Op("OB>", "*AC2", "5"));
        yield return Always("Item: area size I, Q", "AC3 = size of the item's area in bytes: 16 for I and Q.", Op("MOVW", "16", "AC3"));
        yield return new NetworkBuilder("Item: area size M", "M: 32 bytes.").Op("LDB=", "*AC2", "3").Op("MOVW", "32", "AC3").Build();
        yield return new NetworkBuilder("Item: area size V", $"V: {c.VBytes} bytes on this CPU.").Op("LDB=", "*AC2", "4").Op("MOVW", Dec(c.VBytes), "AC3").Build();
        yield return new NetworkBuilder("Item: area size SM", $"SM: {c.SmBytes} bytes on this CPU.").Op("LDB=", "*AC2", "5").Op("MOVW", Dec(c.SmBytes), "AC3").Build();
        yield return Always("Item: to OFFSET", "AC2 points at OFFSET (high byte first).", Op("INCD", "AC2"));
        yield return JumpIf(
            "Item: OFFSET beyond every area", "OFFSET >= 16384 is past every area (and would not fit a signed word): error 02.",
            e02, Op("LDB>=", "*AC2", "16#40"));
        yield return Always(
            "Item: room left in the area", "AC3 = area size - OFFSET; AC2 on to LENGTH.",
            Op("MOVW", "*AC2", "AC0"), Op("-I", "AC0", "AC3"), Op("INCD", "AC2"), Op("INCD", "AC2"));
        yield return JumpIf("Item: OFFSET at or past the end", "No byte left from OFFSET on: error 02.", e02, Op("LDW<=", "AC3", "0"));
        yield return JumpIf(
            "Item: OFFSET + LENGTH past the end", "Fewer than 256 bytes left and LENGTH larger than that: error 02.",
            e02, Op("LDW<", "AC3", "256"), Op("AB>", "*AC2", "AC3"));
        yield return Always(
            "Item: add LENGTH, next item", "AC1 = AC1 + LENGTH; AC2 to the next AREA; one item fewer.",
            Op("BTI", "*AC2", "AC0"), Op("+I", "AC0", "AC1"), Op("INCD", "AC2"), Op("DECB", l.B(I)), Op("DECB", l.B(Budget)));
        foreach (var network in SlicePart.ItemLoopEnd(c, SlicePart.CheckItemsResume, HandlerLabels.CheckItems, "Item"))
        {
            yield return network;
        }

        yield return SlicePart.Pause(c, "Items checked", SlicePart.StepItemsChecked);
        yield return Label(SlicePart.ItemsChecked, "items checked");
        yield return JumpIf(
            "Items checked: WRITE and WRITE BIT", "Their one block passed: on to the write checks.",
            HandlerLabels.Writable, Op("LDB=", l.B(Cmd), Dec(CommandCode.Write)), Op("OB=", l.B(Cmd), Dec(CommandCode.WriteBit)));
        yield return Always(
            "Items checked: 2D + 4N", "AC0 = 2 x (sum of lengths) + 4 x COUNT.",
            Op("MOVW", "AC1", "AC0"), Op("+I", "AC1", "AC0"), Op("BTI", l.B(N), "AC3"), Op("SLW", "AC3", "2"), Op("+I", "AC3", "AC0"));
        yield return JumpIf(
            "Items checked: too much data", $"2D + 4N > {ReadReplyRoom}: the reply would reach the descriptors, error 04.", e04, Op("LDW>", "AC0", Dec(ReadReplyRoom)));
        yield return Always("Items checked: keep D", "D = sum of the lengths (at most 119 now).", Op("MOVB", "AC1", l.B(D)));
        yield return JumpIf("Items checked: DEFINE LIST", "On to the capacity rule.", HandlerLabels.DefineItemsChecked, Op("LDB=", l.B(Cmd), Dec(CommandCode.DefineList)));
        yield return JumpIf("Items checked: READ", "On to the reply.", HandlerLabels.ReadItemsChecked, Op("LD", "SM0.0"));
    }
}
