using OperatorPanel.Core.Link;
using OperatorPanel.Core.Protocol;
using OperatorPanel.StlGen.Model;
using static OperatorPanel.StlGen.Handler.HandlerContext;
using static OperatorPanel.StlGen.Handler.HandlerLayout;
using static OperatorPanel.StlGen.Handler.HandlerSnippets;

namespace OperatorPanel.StlGen.Handler;

/// <summary>
/// 08 READ CHANGES (docs/protocol-v2.md, "READ CHANGES"): binary payload LIST (buffer byte 8) and FLAGS (9). Reply K,
/// then K pairs INDEX VALUE, or K = 16#FF and the whole list. Every part runs in OP_PANEL's slices: the comparison
/// chunks of at most <see cref="ChunkBytes"/> bytes while a budget of <see cref="CompareBudget"/> lasts in a scan, the whole list at most <see cref="SlicePart.ItemsPerScan"/>
/// items per scan; nothing runs in an interrupt routine. Whatever a reply reports is what the copy holds afterwards:
/// a changed byte is moved into the copy and sent from there, and a whole list is moved into the copy item by item
/// and sent from there, so a program changing the bytes between two slices never makes the copy and the reply differ.
/// 09 READ CHANGES OF LISTS (<see cref="ChangesOfListsPart"/>) runs each of its lists through the same networks: the
/// list's descriptors, its copy, the comparison's set-up and the comparison, which hands a list of 09 back at its end.
/// </summary>
internal static class ChangesPart
{
    /// <summary>The most bytes of one item in a chunk of the comparison (the link's bound counts one chunk per scan).</summary>
    public const int ChunkBytes = HandlerTurnaround.ChangeChunkBytes;

    /// <summary>
    /// The comparison's budget per scan and what a chunk costs of it besides its bytes: a unit stands for at most
    /// 0.34 ms at the StlTiming figures (a chunk with its item's start 1.6 ms at most, an unchanged byte 0.27 ms, a
    /// changed byte with its pair 0.68 ms), so a scan's chunks stay under 7.2 ms. The budget is exactly one chunk of
    /// <see cref="ChunkBytes"/> changed bytes: the first chunk of a scan is always whole.
    /// </summary>
    public const int ChunkUnits = 5, CompareBudget = ChunkUnits + (2 * ChunkBytes);

    /// <summary>
    /// 09 goes on with its next list (up to 3.6 ms: the entry, the next list's start) only while at least this much of
    /// the budget is left; else in the next scan.
    /// </summary>
    private const int NextListUnits = 12;

    /// <summary>STEP values of READ CHANGES.</summary>
    public const int StepCompare = 12, StepCopyItems = 13, StepCopyToReply = 14;

    /// <summary>
    /// Labels: the comparison (its resume, next chunk, one chunk, the item's area found, done), the whole list (the copy
    /// as the reply, its start, the next item into the copy, that loop's resume, the item's area found).
    /// </summary>
    public const int CompareResume = 100, CompareLoop = 101, CompareChunk = 102, CompareAreaFound = 103, CompareDone = 104,
        CopyToReply = 105, FullWithCopy = 106, CopyItem = 107, CopyItemsResume = 108, CopyAreaFound = 109, CompareBytes = 115;

    /// <summary>Where OP_PANEL goes on in the next scan (added to <see cref="SlicePart"/>'s resumes; none without copies).</summary>
    public static IEnumerable<(int Step, int Label)> Resumes(HandlerContext c) =>
        c.Options.CopyBytes == 0 ? [] : [(StepCompare, CompareResume), (StepCopyItems, CopyItemsResume), (StepCopyToReply, CopyToReply)];

    /// <summary>The first payload character of a reply (after '&lt;', STATION, SEQ, CMD, STATUS, REQCHECK).</summary>
    private const int Payload = ReplyPart.PayloadStart;

    /// <summary>"FF" in the two payload characters of K: the whole list follows.</summary>
    private const string FullMark = "16#4646";

    public static IEnumerable<StlNetwork> Networks(HandlerContext c)
    {
        foreach (var network in Entry(c).Concat(c.Options.CopyBytes == 0 ? [] : Compare(c).Concat(Full(c))))
        {
            yield return network;
        }
    }

    /// <summary>
    /// DEFINE LIST, once it is sure to be stored (LIST, N and D known): the list's copy from CFREE if D bytes fit,
    /// else none. No list stored (MAXD = 0: every stored list has D &gt;= 1 and clearing the lists resets MAXD) means
    /// the copy area is empty; so clearing the lists drops the copies without a byte more in the receive interrupt.
    /// </summary>
    public static IEnumerable<StlNetwork> Allocate(HandlerContext c)
    {
        var l = c.Layout;
        yield return new NetworkBuilder("DEFINE LIST: copies of cleared lists are gone", "No list stored (MAXD = 0): the copy area is free again.")
            .Op("LDB=", l.B(MaxD), "0").Op("MOVB", "0", l.B(CFree)).Build();
        yield return Always(
            "DEFINE LIST: the list's copy state",
            "AC3 points at CSTART of the list: no copy yet (255); CD = D, bit 7 clear: the first READ CHANGES answers the whole list. AC0 = CFREE + D.",
            Op("BTI", l.B(List), "AC0"), Op("ITD", "AC0", "AC0"), Op("MOVD", l.Ptr(CStart1 - 1), "AC3"), Op("+D", "AC0", "AC3"),
            Op("MOVB", Dec(NoCopy), "*AC3"), Op("+D", "4", "AC3"), Op("MOVB", l.B(D), "*AC3"), Op("-D", "4", "AC3"),
            Op("BTI", l.B(CFree), "AC0"), Op("BTI", l.B(D), "AC2"), Op("+I", "AC2", "AC0"));
        yield return new NetworkBuilder(
                "DEFINE LIST: a copy if D bytes are left",
                $"CFREE + D <= {c.Options.CopyBytes}: CSTART = CFREE, CFREE = CFREE + D; else the list has no copy (always the whole list).")
            .Op("LDW<=", "AC0", Dec(c.Options.CopyBytes)).Op("MOVB", l.B(CFree), "*AC3").Op("MOVB", "AC0", l.B(CFree)).Build();
    }

    private static IEnumerable<StlNetwork> Entry(HandlerContext c)
    {
        var l = c.Layout;
        var e07 = HandlerLabels.Error(ProtocolError.ListNotDefined);
        yield return Label(HandlerLabels.ReadChanges, "08 READ CHANGES");
        yield return JumpIf("READ CHANGES: body exactly 5 bytes", $"Error 04 unless count = {RequestChars(2)}.",
            HandlerLabels.Error(ProtocolError.BadLength), Op("LDB<>", l.B(0), RequestChars(2)));
        yield return JumpIf("READ CHANGES: FLAGS", "Only bit 0 (FULL) may be set: error 06.", HandlerLabels.Error(ProtocolError.BadParameter),
            Op("LDB>", l.B(9), Dec(ReadChangesFlags.Full)));
        yield return JumpIf("READ CHANGES: LIST 1-4", "Any other LIST is never defined: error 07.", e07, Op("LDB=", l.B(8), "0"), Op("OB>", l.B(8), "4"));
        yield return Descriptors(c, "READ CHANGES: the list's descriptors", "LIST kept; ", Op("MOVB", l.B(8), l.B(List)));
        yield return JumpIf("READ CHANGES: list not defined", "LCOUNT = 0: error 07.", e07, Op("LDB=", "*AC3", "0"));
        var whole = new NetworkBuilder(
                "READ CHANGES: K = 16#FF for now",
                $"I = item count; K as 'FF' in the first payload characters, data or pairs from buffer byte {Payload + 2} (AC1).")
            .Op("LD", "SM0.0").Op("MOVB", "*AC3", l.B(I)).Op("MOVW", FullMark, l.W(Payload)).Op("MOVD", l.Ptr(Payload + 2), "AC1");
        if (c.Options.CopyBytes == 0)
        {
            yield return whole.Op("MOVB", Dec(SlicePart.StepBuildItems), l.B(Step)).Op("JMP", Dec(SlicePart.Yield)).Build();
            yield break;
        }

        yield return whole.Op("+D", Dec(CStart1 - LCount1), "AC3").Build();
        yield return JumpIf(
            "READ CHANGES: no copy", "CSTART = 255: the whole list, built like READ LIST's from the next scan on.", SlicePart.Yield,
            Op("LDB=", "*AC3", Dec(NoCopy)), Op("MOVB", Dec(SlicePart.StepBuildItems), l.B(Step)));
        yield return Copy(c);
        yield return JumpIf("READ CHANGES: FULL asked or no valid copy", "FLAGS bit 0, or CD bit 7 clear: the whole list into the copy and the reply.",
            FullWithCopy, Op("LD", l.Bit(9, 0)), Op("OB<", "*AC3", Dec(CopyValid)));
        yield return CompareSetUp(c, "with K >= N pairs (2K >= D) the whole list is not longer");
        yield return SlicePart.Pause(c, "READ CHANGES: comparison ready", StepCompare);
    }

    /// <summary>
    /// The list whose id is in LIST (set by <paramref name="first"/> or before): AC3 at its START, AC2 at its first
    /// descriptor, then AC3 at its LCOUNT.
    /// </summary>
    public static StlNetwork Descriptors(HandlerContext c, string title, string kept, params (string, string[])[] first)
    {
        var l = c.Layout;
        return Always(
            title,
            kept + "AC3 points at START of the list, AC2 at its first descriptor; then AC3 at LCOUNT.",
            [.. first, Op("MOVD", l.Ptr(Start1 - 1), "AC3"), Op("BTI", l.B(List), "AC0"), Op("ITD", "AC0", "AC0"),
            Op("+D", "AC0", "AC3"), Op("MOVD", l.Ptr(0), "AC2"), Op("BTI", "*AC3", "AC0"), Op("ITD", "AC0", "AC0"), Op("+D", "AC0", "AC2"), Op("+D", "4", "AC3")]);
    }

    /// <summary>In: AC3 at CSTART of a list with a copy. Out: AC0 at its first copy byte, AC3 at CD, D = the list's data bytes.</summary>
    public static StlNetwork Copy(HandlerContext c)
    {
        var l = c.Layout;
        return Always(
            "READ CHANGES: the copy",
            "AC0 = first copy byte of the list (copy area + CSTART, through OP_AC0 as scratch); D = CD with its valid bit; AC3 on to CD.",
            Op("MOVD", l.Ptr(CopyArea), "AC0"), Op("MOVD", "0", l.Dw(Save)), Op("MOVB", "*AC3", l.B(Save + 3)), Op("+D", l.Dw(Save), "AC0"),
            Op("+D", "4", "AC3"), Op("MOVB", "*AC3", l.B(D)), Op("ANDB", Hex(~CopyValid & 0xFF), l.B(D)));
    }

    /// <summary>
    /// Before the comparison of a list with a valid copy (AC0 at the copy, AC2 at the descriptors): the counters, N =
    /// (D + 1) / 2, and the pointers where <see cref="Compare"/> wants them.
    /// </summary>
    public static StlNetwork CompareSetUp(HandlerContext c, string why)
    {
        var l = c.Layout;
        return Always(
            "READ CHANGES: compare with the copy",
            $"K = 0, INDEX = 0, no item begun (CLEFT = 0); N = (D + 1) / 2: {why}. "
            + "Only AC1-AC3 can be pointers: the copy pointer goes to AC2, the descriptor pointer waits in AC0 (OP_AC2 as scratch).",
            Op("MOVB", "0", l.B(K)), Op("MOVB", "0", l.B(PairIndex)), Op("MOVB", "0", l.B(CLeft)), Op("MOVB", l.B(D), l.B(N)),
            Op("INCB", l.B(N)), Op("SRB", l.B(N), "1"), Op("MOVD", "AC0", l.Dw(Save + 8)), Op("MOVD", "AC2", "AC0"), Op("MOVD", l.Dw(Save + 8), "AC2"));
    }

    /// <summary>
    /// AC0 = next descriptor (no pointer: AC3 reads it when an item starts), AC1 = next reply character, AC2 = copy
    /// byte, AC3 = the list's byte in its area. A scan compares chunks of at most <see cref="ChunkBytes"/> bytes of
    /// one item (starting the item when needed), each chunk one FOR loop (OP_AC1's words as its index and count: SAVE
    /// is free within a slice), while CHUNK, the scan's budget (<see cref="CompareBudget"/> units), lasts: a chunk costs
    /// <see cref="ChunkUnits"/> units and one per byte, a changed byte one more, and its run is cut to what the budget
    /// holds were every byte changed, so the first chunk of a scan is always whole. A changed byte goes into the copy;
    /// its pair is written while K &lt; N; at the end K &gt;= N means the whole list, sent from the copy, which then
    /// holds every byte as compared.
    /// </summary>
    private static IEnumerable<StlNetwork> Compare(HandlerContext c)
    {
        var l = c.Layout;
        string index = l.W(Save + 4), run = l.W(Save + 6), left = l.W(Save + 8), budget = l.W(Chunk);
        yield return Label(CompareResume, "READ CHANGES: comparison, this scan's chunks");
        yield return Always("Comparison: budget for this scan", $"{CompareBudget} units: a whole chunk of {ChunkBytes} bytes even if all of them changed.",
            Op("MOVW", Dec(CompareBudget), budget));
        yield return Label(CompareLoop, "READ CHANGES: next chunk");
        yield return JumpIf(
            "Comparison: scan's budget used", $"Less than a chunk of one changed byte ({ChunkUnits + 2} units) left: the next scan goes on.", SlicePart.Yield,
            Op("LDW<", budget, Dec(ChunkUnits + 2)));
        yield return JumpIf("Comparison: bytes left in the item", "On to the chunk.", CompareChunk, Op("LDB<>", l.B(CLeft), "0"));
        yield return JumpIf("Comparison: all items compared", "No item left: the pairs are the reply.", CompareDone, Op("LDB=", l.B(I), "0"));
        yield return Always(
            "Comparison: the next item",
            "AC3 reads the descriptor at AC0: AREA into OP_AC3's first byte, OFFSET into OP_AC0, CLEFT = LENGTH; AC0 to the next descriptor; one item fewer.",
            Op("MOVD", "AC0", "AC3"), Op("MOVB", "*AC3", l.B(Save + 12)), Op("INCD", "AC3"), Op("ITD", "*AC3", l.Dw(Save)), Op("+D", "2", "AC3"),
            Op("MOVB", "*AC3", l.B(CLeft)), Op("+D", "4", "AC0"), Op("DECB", l.B(I)));
        foreach (var network in AreaStart(l.B(Save + 12), CompareAreaFound))
        {
            yield return network;
        }

        yield return Always("Comparison: the item's first byte", "AC3 = area start + OFFSET.", Op("+D", l.Dw(Save), "AC3"));
        yield return Label(CompareChunk, "READ CHANGES: one chunk");
        yield return Always(
            "Comparison: chunk length", $"Run = CLEFT, CLEFT = 0 (the whole item); left = the bytes the budget holds were all of them changed: (budget - {ChunkUnits}) / 2.",
            Op("BTI", l.B(CLeft), run), Op("MOVB", "0", l.B(CLeft)), Op("MOVW", budget, left), Op("-I", Dec(ChunkUnits), left), Op("SRW", left, "1"));
        yield return new NetworkBuilder(
                "Comparison: at most what the budget holds", $"Run > left (never more than {ChunkBytes}): CLEFT = run - left, the rest of the item; run = left.")
            .Op("LDW>", run, left).Op("-I", left, run).Op("MOVB", l.B(Save + 7), l.B(CLeft)).Op("MOVW", left, run).Build();
        yield return JumpIf(
            "Comparison: not 4 bytes",
            "Any other chunk byte by byte. A jump, not a contact before the double-word compare: a compare contact reads its operands whatever "
            + "the logic stack holds, and a double word at one of an area's last 3 bytes (or the copy area's, the last V bytes) is out of range.",
            CompareBytes, Op("LDW<>", run, "4"));
        yield return new NetworkBuilder(
                "Comparison: 4 bytes unchanged",
                $"A chunk of 4 bytes equal to the copy (a double word, the commonest item): both pointers and INDEX (the CRC word's high byte) on by 4,",
                $"{ChunkUnits + 1} units of the budget, the next chunk. Else byte by byte.")
            .Op("LDD=", "*AC3", "*AC2").Op("+D", "4", "AC3").Op("+D", "4", "AC2").Op("+I", Dec(4 * 256), l.W(PairIndex))
            .Op("-I", Dec(ChunkUnits + 1), budget).Op("JMP", Dec(CompareLoop)).Build();
        yield return Label(CompareBytes, "READ CHANGES: a chunk byte by byte");
        yield return Always(
            "Comparison: the chunk's bytes", $"Budget - {ChunkUnits} - run; a FOR loop over run bytes.",
            Op("-I", run, budget), Op("-I", Dec(ChunkUnits), budget), Op("FOR", index, "1", run));
        yield return new NetworkBuilder(
                "Comparison: one byte",
                "Changed: the copy takes the new value, VALUE = the copy's byte (what the pair reports), one budget unit more, one change more;",
                "while K < N (the pairs shorter than the whole list) INDEX and VALUE as 4 characters at AC1.")
            .Op("LDB<>", "*AC3", "*AC2").Op("MOVB", "*AC3", "*AC2").Op("MOVB", "*AC2", l.B(PairValue)).Op("DECW", budget).Op("INCB", l.B(K))
            .Op("AB<", l.B(K), l.B(N)).Op("HTA", l.B(PairIndex), "*AC1", "4").Op("+D", "4", "AC1").Build();
        yield return Always("Comparison: next byte", "Byte and copy pointers on, INDEX + 1.",
            Op("INCD", "AC3"), Op("INCD", "AC2"), Op("INCB", l.B(PairIndex)));
        yield return new NetworkBuilder("Comparison: end of the chunk").Op("NEXT").Build();
        yield return JumpIf("Comparison: go on", "Next chunk or item.", CompareLoop, Op("LD", "SM0.0"));
        yield return Label(CompareDone, "READ CHANGES: comparison done");
        yield return JumpIf(
            "Comparison: 09 late in the scan", $"Less than {NextListUnits} units left: the entry and the next list in the next scan (it finds no item left).",
            SlicePart.Yield, Op("LDW<", budget, Dec(NextListUnits)), Op("AB=", l.B(Cmd), Dec(CommandCode.ReadChangesOfLists)));
        yield return JumpIf(
            "Comparison: one list of 09", "READ CHANGES OF LISTS goes on with its entry for this list.", ChangesOfListsPart.ListCompared,
            Op("LDB=", l.B(Cmd), Dec(CommandCode.ReadChangesOfLists)));
        yield return JumpIf(
            "Comparison: pairs not shorter",
            "K >= N (2K >= D): the whole list instead. The copy took every changed byte, so it holds the list as compared: the next scan sends it (AC1 = its end).",
            SlicePart.Yield, Op("LDB>=", l.B(K), l.B(N)), Op("MOVD", "AC2", "AC1"), Op("MOVB", Dec(StepCopyToReply), l.B(Step)));
        yield return Always(
            "READ CHANGES: K pairs", "K as the first 2 payload characters; STATUS 00; finish the reply (AC1 is after the pairs).",
            Op("HTA", l.B(K), l.B(Payload), "2"), Op("MOVB", "0", l.B(List)), Op("JMP", Dec(HandlerLabels.Finish)));
    }

    /// <summary>
    /// The whole list into the copy item by item, then the copy as characters: the reply and the copy agree. In: AC0 at
    /// the first copy byte, AC2 at the first descriptor, AC3 at CD, I = item count.
    /// </summary>
    private static IEnumerable<StlNetwork> Full(HandlerContext c)
    {
        var l = c.Layout;
        yield return Label(FullWithCopy, "READ CHANGES: the whole list into the copy");
        yield return Always(
            "READ CHANGES: the copy is renewed", "CD bit 7 set: after this reply the copy holds what it reports. AC1 = the copy pointer (AC0 is no pointer).",
            Op("ORB", Hex(CopyValid), "*AC3"), Op("MOVD", "AC0", "AC1"));
        yield return SlicePart.Pause(c, "READ CHANGES: whole list ready", StepCopyItems);
        foreach (var network in SlicePart.ItemLoop(c, CopyItemsResume, CopyItem, SlicePart.ItemsPerScan, "READ CHANGES: next item into the copy"))
        {
            yield return network;
        }

        foreach (var network in AreaStart("*AC2", CopyAreaFound))
        {
            yield return network;
        }

        yield return Always(
            "Whole list: the item into the copy",
            "AC3 = area start + OFFSET; BMB LENGTH bytes to the copy (AC1); AC1 and AC2 on; one item fewer (OP_AC0, OP_AC1 as scratch).",
            Op("INCD", "AC2"), Op("ITD", "*AC2", l.Dw(Save)), Op("+D", l.Dw(Save), "AC3"), Op("INCD", "AC2"), Op("INCD", "AC2"),
            Op("BMB", "*AC3", "*AC1", "*AC2"), Op("BTI", "*AC2", l.W(Save + 4)), Op("ITD", l.W(Save + 4), l.Dw(Save)), Op("+D", l.Dw(Save), "AC1"),
            Op("INCD", "AC2"), Op("DECB", l.B(I)), Op("DECB", l.B(Budget)));
        foreach (var network in SlicePart.ItemLoopEnd(c, CopyItemsResume, CopyItem, "Whole list"))
        {
            yield return network;
        }

        yield return SlicePart.Pause(c, "READ CHANGES: the whole list is in the copy", StepCopyToReply);
        yield return Label(CopyToReply, "READ CHANGES: the copy as the reply");
        yield return Always(
            "Whole list: the copy as characters",
            $"AC2 = AC1 - D, the first copy byte; HTA 2D characters (K as scratch for the count) to buffer byte {Payload + 2}; AC1 after them; STATUS 00.",
            Op("MOVD", "0", l.Dw(Save)), Op("MOVB", l.B(D), l.B(Save + 3)), Op("MOVD", "AC1", "AC2"), Op("-D", l.Dw(Save), "AC2"), Op("MOVB", l.B(D), l.B(K)),
            Op("SLB", l.B(K), "1"), Op("HTA", "*AC2", l.B(Payload + 2), l.B(K)), Op("MOVD", l.Ptr(Payload + 2), "AC1"), Op("+D", l.Dw(Save), "AC1"), Op("+D", l.Dw(Save), "AC1"),
            Op("MOVB", "0", l.B(List)), Op("JMP", Dec(HandlerLabels.Finish)));
    }
}
