using OperatorPanel.Core.Protocol;
using OperatorPanel.StlGen.Model;
using static OperatorPanel.StlGen.Handler.HandlerContext;
using static OperatorPanel.StlGen.Handler.HandlerLayout;
using static OperatorPanel.StlGen.Handler.HandlerSnippets;

namespace OperatorPanel.StlGen.Handler;

/// <summary>
/// 09 READ CHANGES OF LISTS (docs/protocol-v2.md, "READ CHANGES OF LISTS"): binary payload MASK (buffer byte 8). One
/// entry per list in MASK, ascending: K and K pairs, or K = 16#FE (REREAD) and the list's copy invalid. Each list goes
/// through <see cref="ChangesPart"/>'s comparison, a chunk per scan; MASK in byte 8 loses each list's bit as the list
/// is taken, and ENTRY holds the buffer byte where the next entry's K goes. The pairs are written only while they fit:
/// N, the pairs the comparison may write, is the smaller of (D + 1) / 2 (2K &gt;= D: REREAD) and the room before
/// LAST_FREE, keeping 2 characters for every later list's K; K &gt;= N is REREAD either way, so no pair ever reaches
/// the stored descriptors.
/// </summary>
internal static class ChangesOfListsPart
{
    /// <summary>Labels: the next list in MASK, its start, its REREAD entry, its pairs entry, the end of the reply.</summary>
    public const int NextList = 110, ListStart = 111, ListReread = 112, ListCompared = 113, ListsDone = 114;

    /// <summary>STEP after a REREAD entry: the next list in the next scan (four lists' starts in one scan would take too long).</summary>
    public const int StepNextList = 15;

    /// <summary>Where OP_PANEL goes on in the next scan (added to <see cref="SlicePart"/>'s resumes).</summary>
    public static IEnumerable<(int Step, int Label)> Resumes => [(StepNextList, NextList)];

    /// <summary>"FE" in the two characters of K: REREAD.</summary>
    private const string RereadMark = "16#4645";

    /// <summary>The characters after the last payload character: the 4 check characters, then '&gt;' (the reply's count).</summary>
    private const int ReplyTail = CheckCharacters.Count;

    public static IEnumerable<StlNetwork> Networks(HandlerContext c)
    {
        var l = c.Layout;
        yield return Label(HandlerLabels.ReadChangesOfLists, "09 READ CHANGES OF LISTS");
        yield return JumpIf("READ CHANGES OF LISTS: body exactly 4 bytes", $"Error 04 unless count = {RequestChars(1)}.",
            HandlerLabels.Error(ProtocolError.BadLength), Op("LDB<>", l.B(0), RequestChars(1)));
        yield return JumpIf("READ CHANGES OF LISTS: MASK", "MASK 0, or a bit above bit 3 (lists 1-4 only): error 06.",
            HandlerLabels.Error(ProtocolError.BadParameter), Op("LDB=", l.B(8), "0"), Op("OB>", l.B(8), Dec(ProtocolLimits.ListMaskBits)));
        for (var list = 1; list <= ProtocolLimits.MaxLists; list++)
        {
            yield return JumpIf(
                $"READ CHANGES OF LISTS: list {list} defined", $"List {list} in MASK with LCOUNT{list} = 0: error 07.",
                HandlerLabels.Error(ProtocolError.ListNotDefined), Op("LD", l.Bit(8, list - 1)), Op("AB=", l.B(LCount1 + list - 1), "0"));
        }

        yield return Always("READ CHANGES OF LISTS: first entry", $"ENTRY = buffer byte {ReplyPart.PayloadStart}, the first payload character.",
            Op("MOVB", Dec(ReplyPart.PayloadStart), l.B(Entry)));
        foreach (var network in Next(c).Concat(Start(c)).Concat(Entries(c)))
        {
            yield return network;
        }
    }

    /// <summary>The lowest list left in MASK into LIST, its bit cleared; none left: the reply ends at ENTRY.</summary>
    private static IEnumerable<StlNetwork> Next(HandlerContext c)
    {
        var l = c.Layout;
        yield return Label(NextList, "READ CHANGES OF LISTS: next list");
        yield return JumpIf("Lists: every list answered", "MASK = 0: the reply ends here.", ListsDone, Op("LDB=", l.B(8), "0"));
        for (var list = 1; list <= ProtocolLimits.MaxLists; list++)
        {
            yield return new NetworkBuilder($"Lists: list {list}", $"MASK bit {list - 1}: LIST = {list}, the bit cleared.")
                .Op("LD", l.Bit(8, list - 1)).Op("MOVB", Dec(list), l.B(List)).Op("ANDB", Hex(~(1 << (list - 1)) & 0xFF), l.B(8))
                .Op("JMP", Dec(ListStart)).Build();
        }

        yield return Label(ListsDone, "READ CHANGES OF LISTS: every entry written");
        yield return Always(
            "Lists: the reply", "AC1 = buffer byte ENTRY, after the last entry; STATUS 00; finish the reply.",
            Op("MOVD", l.Ptr(0), "AC1"), Op("BTI", l.B(Entry), "AC0"), Op("ITD", "AC0", "AC0"), Op("+D", "AC0", "AC1"),
            Op("MOVB", "0", l.B(List)), Op("JMP", Dec(HandlerLabels.Finish)));
    }

    /// <summary>
    /// The list in LIST: REREAD without a valid copy; else the comparison, with N the most pairs that are both shorter
    /// than the data and fit (see the class summary), and AC1 after ENTRY's 2 characters.
    /// </summary>
    private static IEnumerable<StlNetwork> Start(HandlerContext c)
    {
        var l = c.Layout;
        yield return Label(ListStart, "READ CHANGES OF LISTS: one list");
        if (c.Options.CopyBytes == 0)
        {
            yield return JumpIf("List: no copies in this handler", "Every list is REREAD.", ListReread, Op("LD", "SM0.0"));
            yield break;
        }

        yield return ChangesPart.Descriptors(c, "List: its descriptors", "");
        yield return Always("List: its items", "I = item count; AC3 on to CSTART.", Op("MOVB", "*AC3", l.B(I)), Op("+D", Dec(CStart1 - LCount1), "AC3"));
        yield return JumpIf("List: no copy", "CSTART = 255: REREAD.", ListReread, Op("LDB=", "*AC3", Dec(NoCopy)));
        yield return ChangesPart.Copy(c);
        yield return JumpIf("List: copy not valid", "CD bit 7 clear (no whole list reported since it was defined, or REREAD since): REREAD.",
            ListReread, Op("LDB<", "*AC3", Dec(CopyValid)));
        yield return ChangesPart.CompareSetUp(c, "with K >= N pairs (2K >= D) the list is REREAD");
        yield return Always(
            "List: room for its pairs",
            $"AC3 = LAST_FREE - ENTRY - 2 - {ReplyTail} - 2 x the lists left in MASK: the characters its pairs may take, each of them counting 2 for K.",
            Op("BTI", l.B(LastFree), "AC3"), Op("BTI", l.B(Entry), "AC1"), Op("-I", "AC1", "AC3"), Op("-I", Dec(2 + ReplyTail), "AC3"));
        for (var list = 1; list <= ProtocolLimits.MaxLists; list++)
        {
            yield return new NetworkBuilder($"List: list {list} still to answer", "Its K takes 2 characters.").Op("LD", l.Bit(8, list - 1)).Op("-I", "2", "AC3").Build();
        }

        yield return Always(
            "List: pairs that fit", "AC3 = (characters / 4) + 1: K at least this does not fit. AC1 = N.",
            Op("SRW", "AC3", "2"), Op("INCW", "AC3"), Op("BTI", l.B(N), "AC1"));
        yield return new NetworkBuilder("List: the smaller N", "N = the pairs that fit, when fewer than (D + 1) / 2.")
            .Op("LDW<", "AC3", "AC1").Op("MOVB", "AC3", l.B(N)).Build();
        yield return Always(
            "List: pairs after K", "AC1 = buffer byte ENTRY + 2: the comparison writes the pairs there.",
            Op("BTI", l.B(Entry), "AC3"), Op("ITD", "AC3", "AC3"), Op("MOVD", l.Ptr(2), "AC1"), Op("+D", "AC3", "AC1"));
        yield return SlicePart.Pause(c, "List: comparison ready", ChangesPart.StepCompare);
    }

    /// <summary>The list's entry: K and its pairs (ENTRY after them), or REREAD with the copy invalid (ENTRY + 2).</summary>
    private static IEnumerable<StlNetwork> Entries(HandlerContext c)
    {
        var l = c.Layout;
        if (c.Options.CopyBytes > 0)
        {
            yield return Label(ListCompared, "READ CHANGES OF LISTS: list compared");
            yield return JumpIf("List: pairs not shorter, or do not fit", "K >= N: REREAD.", ListReread, Op("LDB>=", l.B(K), l.B(N)));
            yield return Always(
                "List: K pairs", "K as 2 characters at buffer byte ENTRY; ENTRY = AC1, after the pairs. The copy holds what they report.",
                Op("MOVD", l.Ptr(0), "AC3"), Op("BTI", l.B(Entry), "AC0"), Op("ITD", "AC0", "AC0"), Op("+D", "AC0", "AC3"), Op("HTA", l.B(K), "*AC3", "2"),
                Op("MOVD", "AC1", "AC0"), Op("MOVD", l.Ptr(0), "AC3"), Op("-D", "AC3", "AC0"), Op("MOVB", "AC0", l.B(Entry)), Op("JMP", Dec(NextList)));
        }

        yield return Label(ListReread, "READ CHANGES OF LISTS: REREAD");
        var reread = new NetworkBuilder(
                "List: REREAD", "'FE' at buffer byte ENTRY, ENTRY + 2; the list's copy is invalid: its next READ CHANGES answers the whole list.")
            .Op("LD", "SM0.0").Op("MOVD", l.Ptr(0), "AC1").Op("BTI", l.B(Entry), "AC0").Op("ITD", "AC0", "AC0").Op("+D", "AC0", "AC1")
            .Op("MOVW", RereadMark, "*AC1").Op("INCB", l.B(Entry)).Op("INCB", l.B(Entry));
        if (c.Options.CopyBytes > 0)
        {
            reread.Op("MOVD", l.Ptr(CD1 - 1), "AC3").Op("BTI", l.B(List), "AC0").Op("ITD", "AC0", "AC0").Op("+D", "AC0", "AC3")
                .Op("ANDB", Hex(~CopyValid & 0xFF), "*AC3");
        }

        yield return reread.Build();
        yield return SlicePart.Pause(c, "List: REREAD written", StepNextList);
    }
}
