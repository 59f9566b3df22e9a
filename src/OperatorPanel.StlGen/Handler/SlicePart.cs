using OperatorPanel.StlGen.Model;
using static OperatorPanel.StlGen.Handler.HandlerContext;
using static OperatorPanel.StlGen.Handler.HandlerLayout;
using static OperatorPanel.StlGen.Handler.HandlerSnippets;

namespace OperatorPanel.StlGen.Handler;

/// <summary>
/// OP_PANEL serves a request in slices, one per scan, as the seed paper's cyclic code does (seed 000 section 8): the
/// receive interrupt only sets STEP = 1; every scan OP_PANEL takes AC0-AC3 back from SAVE, goes on where STEP says,
/// and at the end of its slice (a fixed point, or when its loop's budget is used up) keeps AC0-AC3 in SAVE again.
/// A slice is one pass of a character loop, a loop's budget of items, or one straight run between two fixed points;
/// each budget is sized so the slice stays under <see cref="ScanBoundMs"/> at the StlTiming figures. STEP values are
/// 1-15, so a tree of bit tests finds the resume point with at most 4 jumps (a compare and a jump cost 46 us each).
/// </summary>
internal static class SlicePart
{
    /// <summary>Items checked (READ, DEFINE LIST, WRITE) or moved into a copy per scan: about 1.7 ms and 1.2 ms each.</summary>
    public const int ItemsPerScan = 4;

    /// <summary>Items of a reply built per scan: about 1.3 ms each plus 34 us per data byte (at most 116 in all).</summary>
    public const int ReplyItemsPerScan = 3;

    /// <summary>
    /// What the technician notes promise, at the StlTiming figures; HandlerCostTests measures every golden
    /// configuration against them: the longest interrupt routine, the most added to one scan while serving a request
    /// and without one, and the scans a reply takes (WRITE BIT the fewest, a 20-item READ after a cut-off frame the most).
    /// </summary>
    public const string InterruptBoundMs = "0.5", ScanBoundMs = "10", IdleScanBoundMs = "0.2";

    /// <inheritdoc cref="InterruptBoundMs"/>
    public const int FewestScans = 6, MostScans = 60;

    /// <summary>STEP values: where the next scan goes on (0 = no request); all below 16 (see the class summary).</summary>
    public const int StepStart = 1, StepRequestCheck = 2, StepHeader = 3, StepCheckItems = 4, StepItemsChecked = 5,
        StepBuildItems = 6, StepReplyCheck = 7, StepReplyCheckPass = 8, StepWriteReadBack = 9, StepFrameChecked = 10, StepMovePass = 11;

    /// <summary>The bits of STEP the resume tree tests: STEP values are 1 .. 2^StepBits - 1.</summary>
    public const int StepBits = 4;

    /// <summary>The labels OP_PANEL goes on at; 30 and 40 are the item loops' own, 29 and 39 set their budgets first.</summary>
    public const int RequestStart = 70, RequestCheckPass = 71, Header = 72, ItemsChecked = 73, ReplyCheck = 74, ReplyCheckPass = 75,
        WriteReadBack = 76, FrameChecked = 77, MovePass = 78, CheckItemsResume = 29, BuildItemsResume = 39, Yield = 90, KeepWalkers = 91,
        EndOfSlice = 99;

    /// <summary>Labels of the resume tree's inner nodes: 120 + the STEP bits tested so far.</summary>
    private const int TreeLabels = 120;

    private static readonly (int Step, int Label)[] Resumes =
    [
        (StepStart, RequestStart), (StepRequestCheck, RequestCheckPass), (StepHeader, Header), (StepCheckItems, CheckItemsResume),
        (StepItemsChecked, ItemsChecked), (StepBuildItems, BuildItemsResume), (StepReplyCheck, ReplyCheck),
        (StepReplyCheckPass, ReplyCheckPass), (StepWriteReadBack, WriteReadBack), (StepFrameChecked, FrameChecked),
        (StepMovePass, MovePass),
    ];

    /// <summary>The start of the work on a request: nothing to do, or accumulators back and on where STEP says.</summary>
    public static IEnumerable<StlNetwork> Entry(HandlerContext c)
    {
        var l = c.Layout;
        var idle = new NetworkBuilder("No request waiting", "STEP = 0: the port is receiving or sending; nothing to do in this scan.")
            .Op("LDN", l.Bit(Step, 0));
        for (var bit = 1; bit < StepBits; bit++)
        {
            idle.Op("AN", l.Bit(Step, bit));
        }

        yield return idle.Op("JMP", Dec(EndOfSlice)).Build();
        yield return Always(
            "Go on with the request",
            "AC0-AC3 as the last slice left them (the program may have used them since).",
            Op("MOVD", l.Dw(Save), "AC0"), Op("MOVD", l.Dw(Save + 4), "AC1"), Op("MOVD", l.Dw(Save + 8), "AC2"),
            Op("MOVD", l.Dw(Save + 12), "AC3"));
        var resumes = Resumes.Concat(ChangesPart.Resumes(c)).Concat(ChangesOfListsPart.Resumes).ToList();
        var steps = resumes.Select(r => r.Step).ToList();
        ArgumentOutOfRangeException.ThrowIfNotEqual(steps.Distinct().Count(), steps.Count, nameof(resumes));
        ArgumentOutOfRangeException.ThrowIfGreaterThanOrEqual(steps.Max(), 1 << StepBits, nameof(resumes));
        foreach (var network in ResumeTree(c, resumes, StepBits - 1, 0))
        {
            yield return network;
        }
    }

    /// <summary>
    /// The resume points whose STEP agrees with <paramref name="prefix"/> above <paramref name="bit"/>: a leaf jumps to
    /// its label; a node jumps on STEP bit <paramref name="bit"/> set to its upper half (emitted after the lower half).
    /// </summary>
    private static IEnumerable<StlNetwork> ResumeTree(HandlerContext c, IReadOnlyList<(int Step, int Label)> resumes, int bit, int prefix)
    {
        var l = c.Layout;
        if (resumes.Count == 1)
        {
            yield return JumpIf($"STEP {resumes[0].Step}", $"Go on at label {resumes[0].Label}.", resumes[0].Label, Op("LD", "SM0.0"));
            yield break;
        }

        var upper = resumes.Where(r => (r.Step & (1 << bit)) != 0).ToList();
        var lower = resumes.Where(r => (r.Step & (1 << bit)) == 0).ToList();
        if (upper.Count == 0 || lower.Count == 0)
        {
            foreach (var network in ResumeTree(c, resumes, bit - 1, prefix))
            {
                yield return network;
            }

            yield break;
        }

        var upperPrefix = prefix | (1 << bit);
        var target = upper.Count == 1 ? upper[0].Label : TreeLabels + upperPrefix;
        yield return JumpIf(
            $"STEP bit {bit}", upper.Count == 1 ? $"STEP {upper[0].Step}: go on at label {target}." : $"STEP {string.Join(", ", upper.Select(r => r.Step))}: label {target}.",
            target, Op("LD", l.Bit(Step, bit)));
        foreach (var network in ResumeTree(c, lower, bit - 1, prefix))
        {
            yield return network;
        }

        if (upper.Count > 1)
        {
            yield return Label(target, $"STEP {string.Join(", ", upper.Select(r => r.Step))}");
            foreach (var network in ResumeTree(c, upper, bit - 1, upperPrefix))
            {
                yield return network;
            }
        }
    }

    /// <summary>
    /// The resume point of an item loop: this scan's budget of <paramref name="items"/>, then the loop's own label
    /// <paramref name="loop"/>, which its last item jumps back to.
    /// </summary>
    public static IEnumerable<StlNetwork> ItemLoop(HandlerContext c, int resume, int loop, int items, string what)
    {
        yield return Label(resume, $"{what}: this scan's items");
        yield return Always($"{what}: items this scan", $"At most {items} items in this scan.", Op("MOVB", Dec(items), c.Layout.B(Budget)));
        yield return Label(loop, what);
    }

    /// <summary>
    /// The end of an item loop's body (which took one item off I and BUDGET): items left but none for this scan ends the
    /// slice (STEP was set to the loop's before its first scan), items left go back to <paramref name="loop"/>.
    /// </summary>
    public static IEnumerable<StlNetwork> ItemLoopEnd(HandlerContext c, int resume, int loop, string what)
    {
        var l = c.Layout;
        yield return JumpIf(
            $"{what}: scan's items used", $"Items left, none more in this scan: the next scan goes on at label {resume}.", Yield,
            Op("LDB<>", l.B(I), "0"), Op("AB=", l.B(Budget), "0"));
        yield return JumpIf($"{what}: more items", $"Back to label {loop} while items are left.", loop, Op("LDB<>", l.B(I), "0"));
    }

    /// <summary>Ends this scan's slice; the next scan goes on at <paramref name="step"/>.</summary>
    public static StlNetwork Pause(HandlerContext c, string title, int step) =>
        Always(title, $"Enough for one scan: the next scan goes on at STEP {step}.",
            Op("MOVB", Dec(step), c.Layout.B(Step)), Op("JMP", Dec(Yield)));

    /// <summary>The request is done (reply on its way, or silence): nothing left for the next scans.</summary>
    public static (string, string[]) Done(HandlerContext c) => Op("MOVB", "0", c.Layout.B(Step));

    /// <summary>
    /// The last networks of OP_PANEL: keep the accumulators, then the end every slice jumps to. The reply's check jumps
    /// to <see cref="KeepWalkers"/>: it keeps only AC2 and AC3, because SAVE's AC0 and AC1 double words then hold
    /// COVERED and SENT, which the reply's chunks share with the interrupt routines (<see cref="ChunkPart"/>).
    /// </summary>
    public static IEnumerable<StlNetwork> Exit(HandlerContext c)
    {
        var l = c.Layout;
        yield return Label(Yield, "end of this scan's slice");
        yield return Always(
            "Keep AC0 and AC1", "AC0, AC1 to SAVE: the next slice takes them back.", Op("MOVD", "AC0", l.Dw(Save)), Op("MOVD", "AC1", l.Dw(Save + 4)));
        yield return Label(KeepWalkers, "end of a slice that keeps AC2 and AC3 only");
        yield return Always(
            "Keep AC2 and AC3", "AC2, AC3 to SAVE: the next slice takes them back.", Op("MOVD", "AC2", l.Dw(Save + 8)), Op("MOVD", "AC3", l.Dw(Save + 12)));
        yield return Label(EndOfSlice, "back to OB1");
    }

    /// <summary>
    /// A loop over characters, one pass of at most <paramref name="perPass"/> per scan: AC3 counts the characters left
    /// (the caller sets it), AC0 is the FOR index, <paramref name="perCharacter"/> the loop body. With characters left
    /// after the pass, the next scan goes on at <paramref name="passStep"/> (label <paramref name="passLabel"/>).
    /// </summary>
    public static IEnumerable<StlNetwork> Passes(
        HandlerContext c, string what, int perPass, int passLabel, int passStep, IEnumerable<StlNetwork> perCharacter)
    {
        foreach (var network in Pass(c, what, perPass, passLabel, perCharacter))
        {
            yield return network;
        }

        yield return JumpIf($"{what}: characters left", "The next scan goes on with another pass.",
            Yield, Op("LDW>", "AC3", "0"), Op("MOVB", Dec(passStep), c.Layout.B(Step)));
    }

    /// <summary>One pass of <see cref="Passes"/> without its end: the caller decides what follows it.</summary>
    public static IEnumerable<StlNetwork> Pass(HandlerContext c, string what, int perPass, int passLabel, IEnumerable<StlNetwork> perCharacter)
    {
        var l = c.Layout;
        yield return Label(passLabel, $"one pass of the {what}");
        yield return Always($"Pass of the {what}", "CHUNK = characters left.", Op("MOVW", "AC3", l.W(Chunk)));
        yield return new NetworkBuilder("At most one pass worth", $"CHUNK = {perPass} when more characters are left: one pass per scan.")
            .Op("LDW>", "AC3", Dec(perPass)).Op("MOVW", Dec(perPass), l.W(Chunk)).Build();
        yield return Always($"{what}: CHUNK characters", "AC3 = characters left after this pass; AC0 counts the loop.",
            Op("-I", l.W(Chunk), "AC3"), Op("FOR", "AC0", "1", l.W(Chunk)));
        foreach (var network in perCharacter)
        {
            yield return network;
        }

        yield return new NetworkBuilder($"End of the {what} pass").Op("NEXT").Build();
    }
}
