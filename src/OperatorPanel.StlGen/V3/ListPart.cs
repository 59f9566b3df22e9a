using OperatorPanel.Core.Protocol.V3;
using OperatorPanel.StlGen.Model;
using static OperatorPanel.StlGen.Handler.HandlerSnippets;
using static OperatorPanel.StlGen.V3.Context;

namespace OperatorPanel.StlGen.V3;

/// <summary>
/// 06 READ LIST and 07 READ LIST FULL (docs/protocol.md section 2). Each slot's WINDOW (the 4 bytes from its item's
/// first byte) has a copy in C, so an unchanged list is never gathered: 06 with a valid copy compares every window
/// with its copy (phase Compare, unrolled, an ORed group of 8 double word compares, two groups a scan); a group with a
/// differing window goes through phase Changes, which copies each differing window into C and writes its CHANGES entry
/// (slot, window) into R while the entries stay shorter than the list; then UNCHANGED or CHANGES from R. A whole list
/// (07; 06 with the copy not valid, after phase Changes put its windows into C; 06 whose entries would not be shorter)
/// is gathered into R, one group of 8 items a scan (an unrolled BMB each), and answered from there. While the copy is
/// not valid (after DEFINE LIST or 07) every group goes through phase Changes, which fills the copy (20 scans for 32
/// slots, once; an unrolled copy of every window would cost 44 more instructions).
/// </summary>
internal static class ListPart
{
    public static IEnumerable<StlNetwork> Networks(Context c)
    {
        var l = c.Layout;
        yield return Label(Labels.ReadList, "06 READ LIST, 07 READ LIST FULL");
        yield return Refusal.If(l, "READ LIST: a list", "No list defined: 87.", ReplyStatus.ListNotDefined, Op("LDB=", l.B(l.N), "0"));
        yield return JumpIf(
            "READ LIST FULL: the whole list", "The copy is not valid any more (the next 06 answers whole).", Labels.WholeHead,
            Op("LDB=", l.B(l.Cmd), Dec(Command.ReadListFull)), Op("R", l.FlagBit(Layout.CopyValid), "1"));
        yield return ReturnIf(
            "READ LIST: compare", "From group 0 (COUNT) next scan; entries from R byte 6 (TEMP) while below TAIL (R byte 6 + D: entries beyond would not be shorter). The copy not valid: every group goes through phase Changes (its windows into the copy), then the whole list.",
            Op("LD", "SM0.0"), Op("MOVB", "0", l.B(l.Count)), Op("MOVD", l.Ptr(6), l.Dw(l.Temp)), Op("R", l.FlagBit(Layout.Differs), "1"), l.Go(Phase.Compare));
        foreach (var network in Head(c).Concat(Gather(c)).Concat(Compare(c)).Concat(Changes(c)))
        {
            yield return network;
        }
    }

    /// <summary>Source pointer of slot <paramref name="k"/>, as an indirect operand: its window.</summary>
    private static string Window(Layout l, int k) => "*" + l.Dw(l.Slot(k) + 4);

    /// <summary>Label 46: a whole list: gathered into R from the next scan, one group a scan, then its reply.</summary>
    private static IEnumerable<StlNetwork> Head(Context c)
    {
        var l = c.Layout;
        yield return Label(Labels.WholeHead, "a whole list's reply");
        yield return ReturnIf("Whole list: gather", "From group 0, next scan.", Op("LD", "SM0.0"), Op("MOVB", "1", l.B(l.Group)), l.Go(Phase.Gather));
    }

    private static IEnumerable<StlNetwork> Gather(Context c)
    {
        var l = c.Layout;
        var groups = c.Shape.ListItems / HandlerShape.GroupSlots;
        yield return Label(Labels.Gather, "phase Gather: one group of items into R");
        for (var g = 0; g < groups; g++)
        {
            var slots = Enumerable.Range(g * HandlerShape.GroupSlots, HandlerShape.GroupSlots).ToList();
            yield return new NetworkBuilder(
                    $"Gather: group {g}, slots {slots[0]}-{slots[^1]}",
                    $"GROUP bit {g}: each slot BMB its length from its source to its destination in R. No jump past the other groups: their boxes without power flow take 1 us each, a JMP 46 us taken or not.")
                .Op("LD", l.Bit(l.Group, g)).Ops(slots.Select(k => Op("BMB", Window(l, k), "*" + l.Dw(l.Slot(k)), l.B(l.Slot(k) + 8)))).Build();
        }

        yield return ReturnIf("Gather: more groups", "The next group (GROUP's bit at most USED) in the next scan.", Op("LD", "SM0.0"), Op("SLB", l.B(l.Group), "1"), Op("AB<=", l.B(l.Group), l.B(l.Used)));
        yield return DispatchPart.ToReply(c, "Gather done: the whole list", "80 with P = D bytes, in R; its head next scan.", Op("LD", "SM0.0"), Op("BTI", l.B(l.D), l.W(l.Temp)), Op("MOVB", Hex(ReplyStatus.Ok), l.B(l.Status)));
    }

    /// <summary>
    /// Phase Compare: from group COUNT on, two groups a scan at most, unrolled: 8 ORed double word compares of a window
    /// (through its source pointer, 60 us) with its copy. A group with a differing window: phase Changes over it (COUNT =
    /// the group). After the last group: UNCHANGED when no entry was written, CHANGES when the entries are shorter than
    /// the list, else the whole list.
    /// </summary>
    private static IEnumerable<StlNetwork> Compare(Context c)
    {
        var l = c.Layout;
        var groups = c.Shape.ListItems / HandlerShape.GroupSlots;
        yield return Label(Labels.Compare, "phase Compare: each window against its copy");
        // Where the comparison goes on (COUNT 0-4), the common cases first: a jump's test costs 46 us taken or not,
        // contacts 0.37 us. An idle READ LIST starts at group 0 and goes on at group 2; phase Changes returns anywhere.
        // Each test needs only the bits that tell its value from those not yet ruled out.
        string C(int bit) => l.Bit(l.Count, bit);
        (int Group, (string, string[])[] When)[] tests =
        [
            (0, [Op("LDN", C(0)), Op("AN", C(1)), Op("AN", C(2))]), (2, [Op("LDN", C(0)), Op("A", C(1))]), (groups, [Op("LD", C(2))]), (3, [Op("LD", C(1))]),
            (1, [Op("LD", "SM0.0")]),
        ];
        foreach (var (q, when) in tests)
        {
            yield return JumpIf(q == groups ? "Compare: every group done" : $"Compare: from group {q}", $"COUNT = {q}.", q == groups ? Labels.CompareDone : Labels.Quarter + q, when);
        }

        for (var q = 0; q < groups; q++)
        {
            if (q == 0)
            {
                yield return Label(Labels.Quarter, "group 0");
            }
            else
            {
                if (q % 2 == 0)
                {
                    yield return ReturnIf($"Compare: group {q} next scan", string.Empty, Op("LD", "SM0.0"), Op("MOVB", Dec(q), l.B(l.Count)));
                }

                yield return Label(Labels.Quarter + q, $"group {q}");
                yield return JumpIf($"Compare: group {q} in the list?", "USED's bit clear: the comparison is done.", Labels.CompareDone, Op("LDN", l.Bit(l.Used, q)));
            }

            var net = new NetworkBuilder($"Compare: slots {8 * q}-{(8 * q) + 7}", "Any window differing from its copy, or the copy not valid: phase Changes over this group.");
            for (var w = 0; w < HandlerShape.GroupSlots; w++)
            {
                var k = (HandlerShape.GroupSlots * q) + w;
                net.Op(w == 0 ? "LDD<>" : "OD<>", Window(l, k), l.Dw(l.C + (4 * k)));
            }

            yield return net.Op("ON", l.FlagBit(Layout.CopyValid)).Op("MOVB", Dec(q), l.B(l.Count)).Op("JMP", Dec(Labels.Changes)).Build();
        }

        yield return Label(Labels.CompareDone, "every group compared");
        yield return JumpIf("UNCHANGED", "No window differed (FLAGS bit 4): 81, no payload.", Labels.ErrorReply,
            Op("LDN", l.FlagBit(Layout.Differs)), Op("MOVB", Hex(ReplyStatus.Unchanged), l.B(l.Status)));
        yield return JumpIf("Compare: the copy was not valid", "It is now (phase Changes put every window in it): the whole list.", Labels.WholeHead,
            Op("LDN", l.FlagBit(Layout.CopyValid)), Op("S", l.FlagBit(Layout.CopyValid), "1"));
        yield return JumpIf("CHANGES: not shorter", "5 x entries (LAST's first word, set by phase Changes) >= D: the whole list (the copy holds every window already).", Labels.WholeHead,
            Op("LDB>=", l.B(l.Last + 1), l.B(l.D)));
        yield return DispatchPart.ToReply(c, "CHANGES: reply", "88, P entries' bytes in R.", Op("LD", "SM0.0"), Op("MOVW", l.W(l.Last), l.W(l.Temp)), Op("MOVB", Hex(ReplyStatus.Changes), l.B(l.Status)));
        yield return Label(Labels.Changes, "a group differs");
        yield return ReturnIf(
            "Changes: the group",
            "INDEX (in STATUS) = 8 x COUNT; WALK at its first slot's source pointer (Slots + 4 + 72 x COUNT), END 8 slots on; LAST at its first copy (C + 32 x COUNT); the slots from the next scan.",
            Op("LD", "SM0.0"), Op("S", l.FlagBit(Layout.Differs), "1"), Op("BTI", l.B(l.Count), "AC0"), Op("ITD", "AC0", "AC0"), Op("SLD", "AC0", "3"), Op("MOVB", "AC0", l.B(l.Status)),
            Op("MOVD", "AC0", "AC1"), Op("SLD", "AC1", "3"), Op("+D", "AC0", "AC1"), Op("MOVD", l.Ptr(l.Slots + 4), l.Dw(l.Walk)), Op("+D", "AC1", l.Dw(l.Walk)),
            Op("MOVD", l.Dw(l.Walk), l.Dw(l.End)), Op("+D", Dec(HandlerShape.SlotBytes * HandlerShape.GroupSlots), l.Dw(l.End)),
            Op("SLD", "AC0", "2"), Op("MOVD", l.Ptr(l.C), l.Dw(l.Last)), Op("+D", "AC0", l.Dw(l.Last)), l.Go(Phase.Changes));
    }

    /// <summary>Phase Changes: two slots of the group per scan (a loop); at the group's end, phase Compare from the next group.</summary>
    private static IEnumerable<StlNetwork> Changes(Context c)
    {
        var l = c.Layout;
        var index = l.B(l.Status);
        yield return Label(Labels.ChangesLoop, "phase Changes: two slots per scan");
        yield return Always("Changes: pointers", "AC2 at the slot's copy (LAST), AC3 at the next entry (TEMP).", Op("MOVD", l.Dw(l.Last), "AC2"), Op("MOVD", l.Dw(l.Temp), "AC3"));
        for (var k = 0; k < 2; k++)
        {
            // Unrolled, no loop test: a group's 8 slots take exactly 4 scans (a jump's test costs 46 us taken or not).
            yield return new NetworkBuilder("Changes: a slot's window", "AC1 = its source pointer; a window differing from its copy goes into the copy, and its entry, INDEX and the 4 bytes, while below TAIL.")
                .Op("LD", "SM0.0").Op("MOVD", "*" + l.Dw(l.Walk), "AC1").Op("AD<>", "*AC1", "*AC2").Op("MOVD", "*AC1", "*AC2").Op("AD<", "AC3", l.Dw(l.Tail)).Op("MOVB", index, "*AC3")
                .Op("INCD", "AC3").Op("MOVD", "*AC2", "*AC3").Op("+D", "4", "AC3").Build();
            yield return Always("Changes: the next slot", string.Empty, Op("+D", Dec(HandlerShape.SlotBytes), l.Dw(l.Walk)), Op("+D", "4", "AC2"), Op("INCB", index));
        }

        yield return ReturnIf("Changes: more next scan", "Keep the pointers.", Op("LD", "SM0.0"), Op("MOVD", "AC3", l.Dw(l.Temp)), Op("MOVD", "AC2", l.Dw(l.Last)), Op("AD<", l.Dw(l.Walk), l.Dw(l.End)));
        yield return ReturnIf(
            "Changes: the group done", "The entries' bytes so far (TEMP - R byte 6) in LAST's first word; phase Compare from the next group, next scan.",
            Op("LD", "SM0.0"), Op("MOVD", "AC3", "AC0"), Op("MOVD", l.Ptr(6), "AC1"), Op("-D", "AC1", "AC0"), Op("MOVW", "AC0", l.W(l.Last)), Op("INCB", l.B(l.Count)), l.Go(Phase.Compare));
    }
}
