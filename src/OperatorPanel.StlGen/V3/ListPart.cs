using OperatorPanel.Core.Protocol.V3;
using OperatorPanel.StlGen.Model;
using static OperatorPanel.StlGen.Handler.HandlerSnippets;
using static OperatorPanel.StlGen.V3.Context;

namespace OperatorPanel.StlGen.V3;

/// <summary>
/// 06 READ LIST and 07 READ LIST FULL (docs/protocol.md section 2), a phase per scan. 07: its head in L at once, then
/// the gather, one group of 8 slots per scan (an unrolled BMB per slot), each group's bytes sent as soon as they are
/// there; then the reply's check; the copy is not valid afterwards. 06: the gather; then G against the copy C, unrolled
/// in quarters of 32 bytes: a quarter with a differing double word (every quarter when the copy is not valid) goes
/// through phase Changes, which copies each differing double word into C and writes its CHANGES entry into R while the
/// entries stay shorter than the list. Then UNCHANGED, CHANGES, or the whole list (C holds G already): when the entries
/// are not shorter, or the copy was not valid.
/// </summary>
internal static class ListPart
{
    /// <summary>Double words phase Changes takes per scan: about 0.3 ms each, 0.7 with an entry.</summary>
    private const int ChangesPerScan = 2;

    /// <summary>A pointer beyond every reply: SENT while a comparison's reply is unknown, so nothing is sent.</summary>
    private const string Nowhere = "16#7FFFFFFF";

    public static IEnumerable<StlNetwork> Networks(Context c)
    {
        var l = c.Layout;
        yield return Label(Labels.ReadList, "06 READ LIST, 07 READ LIST FULL");
        yield return Refusal.If(l, "READ LIST: a list", "No list defined: 87.", ReplyStatus.ListNotDefined, Op("LDB=", l.B(l.N), "0"));
        yield return Always("READ LIST: gather from group 0", "Zero the 4 bytes after the data (a reply's check may be there); not a whole list yet.",
            Op("MOVD", "0", "*" + l.Dw(l.Tail)), Op("MOVB", "1", l.B(l.Group)), Op("R", l.FlagBit(Layout.Whole), "1"));
        yield return JumpIf("READ LIST FULL: the whole list", "07: its head now; the copy is not valid any more (the next 06 answers whole).", Labels.WholeHead,
            Op("LDB=", l.B(l.Cmd), Dec(Command.ReadListFull)), Op("R", l.FlagBit(Layout.CopyValid), "1"));
        yield return ReturnIf(
            "READ LIST: a comparison",
            "Nothing is sent until the reply is known; the comparison from quarter 0 (COUNT); entries from R byte 6 (TEMP) while below R byte 6 + D (LAST: entries beyond would not be shorter); the gather next scan.", Op("LD", "SM0.0"), Op("MOVD", Nowhere, l.Dw(l.Sent)), Op("MOVB", "0", l.B(l.Count)), Op("MOVD", l.Ptr(6), l.Dw(l.Temp)), Op("BTI", l.B(l.D), "AC0"),
            Op("ITD", "AC0", "AC0"), Op("MOVD", l.Ptr(6), l.Dw(l.Last)), Op("+D", "AC0", l.Dw(l.Last)), l.Go(Phase.Gather));
        foreach (var network in Head(c).Concat(Gather(c)).Concat(Compare(c)).Concat(Changes(c)))
        {
            yield return network;
        }
    }

    /// <summary>Label 46: the whole list's head in L; from the dispatch (then the gather) or after the comparison (then the data and the check).</summary>
    private static IEnumerable<StlNetwork> Head(Context c)
    {
        var l = c.Layout;
        yield return Label(Labels.WholeHead, "a whole list's reply");
        yield return Always(
            "Whole list: head",
            "80 and REQCHECK after L's '<' and LEN (set by DEFINE LIST); SENT = L's count byte, COVERED = REQCHECK's last byte; the check walks from '<' to TAIL.",
            Op("MOVB", Hex(ReplyStatus.Ok), l.B(l.L + 3)), Op("MOVW", l.W(l.Rx + 2), l.W(l.L + 4)), Op("MOVD", l.Ptr(l.L), l.Dw(l.Sent)),
            Op("MOVD", l.Ptr(l.L + 5), l.Dw(l.Covered)), Op("MOVD", l.Dw(l.Tail), l.Dw(l.End)),
            Op("MOVD", l.Ptr(l.L + 1), l.Dw(l.Walk)), Op("MOVD", "0", l.Dw(l.SumA)), Op("MOVW", "0", l.W(l.SumB)), Op("S", l.FlagBit(Layout.Whole), "1"));
        yield return ReturnIf("Whole list: gather next", "From the dispatch: head and data leave when the last group is gathered.", Op("LDB<", l.B(l.Group), l.B(l.Groups)), l.Go(Phase.Gather));
        yield return JumpIf("Whole list: all of it", "After the comparison, G gathered: head and data leave now, the check from the next scan.", Labels.Publish,
            Op("LD", "SM0.0"), Op("MOVD", l.Dw(l.Tail), l.Dw(l.Covered)), Op("DECD", l.Dw(l.Covered)), l.GoReplyCheck());
    }

    private static IEnumerable<StlNetwork> Gather(Context c)
    {
        var l = c.Layout;
        var groups = c.Shape.ListItems / HandlerShape.GroupSlots;
        yield return Label(Labels.Gather, "phase Gather: one group of slots");
        for (var g = 0; g < groups; g++)
        {
            var slots = Enumerable.Range(g * HandlerShape.GroupSlots, HandlerShape.GroupSlots).ToList();
            yield return new NetworkBuilder(
                    $"Gather: group {g}, slots {slots[0]}-{slots[^1]}",
                    $"GROUP bit {g}: each slot BMB its length from its source to its destination; COVERED = where the next slot's bytes go (the data's end after the last). No jump past the other groups: their boxes without power flow take 1 us each, a JMP 46 us taken or not.")
                .Op("LD", l.Bit(l.Group, g)).Ops(slots.Select(k => Op("BMB", "*" + l.Dw(l.Slot(k) + 4), "*" + l.Dw(l.Slot(k)), l.B(l.Slot(k) + 8))))
                .Op("MOVD", l.Dw(l.Slot(slots[^1] + 1)), l.Dw(l.Covered)).Build();
        }

        yield return Always("Gather: on", "COVERED = the group's last byte; the next group.", Op("DECD", l.Dw(l.Covered)), Op("SLB", l.B(l.Group), "1"));
        // Nothing leaves before the whole list is gathered: a second chunk's XMT count goes into the byte before it (the
        // first chunk's last), which the check, walked only after the gather, would then read instead of the data.
        yield return ReturnIf("Gather: more groups", "The next group in the next scan; nothing leaves yet: the next chunk's count would overwrite a byte the check has not read.",
            Op("LDB<", l.B(l.Group), l.B(l.Groups)));
        yield return JumpIf("Gather done: the whole list's check", "Head and data leave now in one chunk, the check from the next scan.", Labels.Publish,
            Op("LD", l.FlagBit(Layout.Whole)), l.GoReplyCheck());
        yield return ReturnIf("Gather done: compare", "In the next scan.", Op("LD", "SM0.0"), l.Go(Phase.Compare));
    }

    /// <summary>
    /// Phase Compare: G against C from quarter COUNT on, two quarters of 32 bytes a scan at most, unrolled. A quarter with
    /// a differing double word: phase Changes over it (COUNT = the quarter). After the last quarter: UNCHANGED when no
    /// entry was written, CHANGES when the entries are shorter than the list, else the whole list.
    /// </summary>
    private static IEnumerable<StlNetwork> Compare(Context c)
    {
        var l = c.Layout;
        var quarters = (c.Shape.ListBytes + 31) / 32;
        yield return Label(Labels.Compare, "phase Compare: G against the copy");
        for (var q = quarters; q >= 1; q--)
        {
            yield return JumpIf(
                q == quarters ? "Compare: every quarter done" : $"Compare: from quarter {q}?",
                "COUNT's bits, the highest quarter first: COUNT has every bit of this quarter's number only when it is at least this one, and the higher ones went before (a contact takes 0.37 us, a byte compare 46).",
                q == quarters ? Labels.CompareDone : Labels.Quarter + q,
                [.. BitsOf(q).Select((bit, i) => Op(i == 0 ? "LD" : "A", l.Bit(l.Count, bit)))]);
        }

        for (var q = 0; q < quarters; q++)
        {
            if (q > 0)
            {
                if (q % 2 == 0)
                {
                    yield return ReturnIf($"Compare: quarter {q} next scan", string.Empty, Op("LD", "SM0.0"), Op("MOVB", Dec(q), l.B(l.Count)));
                }

                yield return Label(Labels.Quarter + q, $"quarter {q}");
                yield return JumpIf($"Compare: D within {32 * q}", "The rest is not data: the comparison is done.", Labels.CompareDone, Op("LDB<=", l.B(l.D), Dec(32 * q)));
            }

            var net = new NetworkBuilder($"Compare: bytes {32 * q}-{(32 * q) + 31}", "Any double word differing from the copy, or the copy not valid: phase Changes over this quarter.");
            for (var w = 0; w < 8 && (32 * q) + (4 * w) < c.Shape.ListBytes; w++)
            {
                var at = (32 * q) + (4 * w);
                net.Op(w == 0 ? "LDD<>" : "OD<>", l.Dw(l.G + at), l.Dw(l.C + at));
            }

            yield return net.Op("ON", l.FlagBit(Layout.CopyValid)).Op("MOVB", Dec(q), l.B(l.Count)).Op("JMP", Dec(Labels.Changes)).Build();
        }

        yield return Label(Labels.CompareDone, "every quarter compared");
        yield return JumpIf("Compare: the copy was not valid", "It is now (phase Changes made it G): the whole list.", Labels.WholeHead,
            Op("LDN", l.FlagBit(Layout.CopyValid)), Op("S", l.FlagBit(Layout.CopyValid), "1"));
        yield return Always("CHANGES: P", "P = the entries' bytes (TEMP - R byte 6).",
            Op("MOVD", l.Dw(l.Temp), "AC0"), Op("MOVD", l.Ptr(6), "AC1"), Op("-D", "AC1", "AC0"), Op("MOVW", "AC0", l.W(l.Temp)));
        yield return JumpIf("UNCHANGED", "No entry written: 81, no payload.", Labels.ErrorReply,
            Op("LDW=", l.W(l.Temp), "0"), Op("MOVB", Hex(ReplyStatus.Unchanged), l.B(l.Status)));
        yield return JumpIf("CHANGES: not shorter", "5 x entries >= D: the whole list (the copy holds G already).", Labels.WholeHead,
            Op("LDB>=", l.B(l.Temp + 1), l.B(l.D)));
        yield return DispatchPart.ToReply(c, "CHANGES: reply", "88, the entries in R.", Op("LD", "SM0.0"), Op("MOVB", Hex(ReplyStatus.Changes), l.B(l.Status)));
        yield return Label(Labels.Changes, "a quarter differs");
        yield return Always(
            "Changes: the quarter",
            "WALK in G and COVERED in C at its first double word, END at its end (at most TAIL); INDEX (in STATUS) = 8 x COUNT.",
            Op("BTI", l.B(l.Count), "AC0"), Op("ITD", "AC0", "AC0"), Op("SLD", "AC0", "3"), Op("MOVB", "AC0", l.B(l.Status)), Op("SLD", "AC0", "2"),
            Op("MOVD", l.Ptr(l.G), l.Dw(l.Walk)), Op("+D", "AC0", l.Dw(l.Walk)), Op("MOVD", l.Ptr(l.C), l.Dw(l.Covered)), Op("+D", "AC0", l.Dw(l.Covered)),
            Op("MOVD", l.Dw(l.Walk), l.Dw(l.End)), Op("+D", "32", l.Dw(l.End)));
        yield return new NetworkBuilder("Changes: not past TAIL", string.Empty).Op("LDD>", l.Dw(l.End), l.Dw(l.Tail)).Op("MOVD", l.Dw(l.Tail), l.Dw(l.End)).Build();
        yield return ReturnIf("Changes: next scan", string.Empty, Op("LD", "SM0.0"), l.Go(Phase.Changes));
    }

    /// <summary>The set bits of <paramref name="value"/>, lowest first.</summary>
    private static IEnumerable<int> BitsOf(int value) => Enumerable.Range(0, 8).Where(bit => (value & (1 << bit)) != 0);

    /// <summary>Phase Changes: two double words of the quarter per scan, unrolled; at its end, phase Compare from the next quarter.</summary>
    private static IEnumerable<StlNetwork> Changes(Context c)
    {
        var l = c.Layout;
        var index = l.B(l.Status);
        yield return Label(Labels.ChangesLoop, "phase Changes: two double words per scan");
        yield return Always("Changes: pointers", "AC1 in G, AC2 in C, AC3 at the next entry.",
            Op("MOVD", l.Dw(l.Walk), "AC1"), Op("MOVD", l.Dw(l.Covered), "AC2"), Op("MOVD", l.Dw(l.Temp), "AC3"));
        for (var k = 0; k < ChangesPerScan; k++)
        {
            if (k > 0)
            {
                yield return JumpIf("Changes: the quarter's end", string.Empty, Labels.ChangesNext, Op("LDD>=", "AC1", l.Dw(l.End)));
            }

            yield return new NetworkBuilder("Changes: a differing double word", "Into the copy; its entry, INDEX and the 4 bytes, while below the limit (LAST).")
                .Op("LDD<>", "*AC1", "*AC2").Op("MOVD", "*AC1", "*AC2").Op("AD<", "AC3", l.Dw(l.Last)).Op("MOVB", index, "*AC3").Op("INCD", "AC3")
                .Op("MOVD", "*AC1", "*AC3").Op("+D", "4", "AC3").Build();
            yield return Always("Changes: on", string.Empty, Op("+D", "4", "AC1"), Op("+D", "4", "AC2"), Op("INCB", index));
        }

        yield return Label(Labels.ChangesNext, "this scan's double words done");
        yield return Always("Changes: keep the pointers", string.Empty, Op("MOVD", "AC1", l.Dw(l.Walk)), Op("MOVD", "AC2", l.Dw(l.Covered)), Op("MOVD", "AC3", l.Dw(l.Temp)));
        yield return ReturnIf("Changes: more next scan", string.Empty, Op("LDD<", "AC1", l.Dw(l.End)));
        yield return ReturnIf("Changes: the quarter done", "Phase Compare from the next quarter, next scan.", Op("LD", "SM0.0"), Op("INCB", l.B(l.Count)), l.Go(Phase.Compare));
    }
}
