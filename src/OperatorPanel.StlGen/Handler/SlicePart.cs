using OperatorPanel.StlGen.Model;
using static OperatorPanel.StlGen.Handler.HandlerContext;
using static OperatorPanel.StlGen.Handler.HandlerLayout;
using static OperatorPanel.StlGen.Handler.HandlerSnippets;

namespace OperatorPanel.StlGen.Handler;

/// <summary>
/// OP_PANEL serves a request in slices, one per scan, as the seed paper's cyclic code does (seed 000 section 8): the
/// receive interrupt only sets STEP = 1; every scan OP_PANEL takes AC0-AC3 back from SAVE, goes on where STEP says,
/// and at the end of its slice (a fixed point, or when BUDGET loop passes are used up) keeps AC0-AC3 in SAVE again.
/// A slice is at most <see cref="PassesPerScan"/> passes of one loop, or one straight run between two fixed points.
/// </summary>
internal static class SlicePart
{
    /// <summary>Loop passes per scan: frame check passes of <see cref="FrameCheckPart.CharactersPerPass"/> characters, items checked or replied.</summary>
    public const int PassesPerScan = 2;

    /// <summary>
    /// What the technician notes promise, at the StlTiming figures; HandlerCostTests measures every golden
    /// configuration against them: the longest interrupt routine, the most added to one scan while serving a request
    /// and without one, and the scans a reply takes (WRITE BIT the fewest, a 20-item READ after a cut-off frame the most).
    /// </summary>
    public const string InterruptBoundMs = "0.5", ScanBoundMs = "10", IdleScanBoundMs = "0.3";

    /// <inheritdoc cref="InterruptBoundMs"/>
    public const int FewestScans = 8, MostScans = 75;

    /// <summary>STEP values: where the next scan goes on (0 = no request).</summary>
    public const int StepStart = 1, StepRequestCheck = 2, StepHeader = 3, StepCheckItems = 4, StepItemsChecked = 5,
        StepBuildItems = 6, StepReplyCheck = 7, StepReplyCheckPass = 8, StepWriteReadBack = 9, StepFrameChecked = 10, StepMovePass = 11;

    /// <summary>The labels OP_PANEL goes on at; 30 and 40 are the item loops' own.</summary>
    public const int RequestCheckPass = 71, Header = 72, ItemsChecked = 73, ReplyCheck = 74, ReplyCheckPass = 75,
        WriteReadBack = 76, FrameChecked = 77, MovePass = 78, Yield = 90, EndOfSlice = 99;

    private static readonly (int Step, int Label)[] Resumes =
    [
        (StepRequestCheck, RequestCheckPass), (StepHeader, Header), (StepCheckItems, HandlerLabels.CheckItems),
        (StepItemsChecked, ItemsChecked), (StepBuildItems, HandlerLabels.BuildItems), (StepReplyCheck, ReplyCheck),
        (StepReplyCheckPass, ReplyCheckPass), (StepWriteReadBack, WriteReadBack), (StepFrameChecked, FrameChecked),
        (StepMovePass, MovePass),
    ];

    /// <summary>The start of the work on a request: nothing to do, or accumulators back and on where STEP says.</summary>
    public static IEnumerable<StlNetwork> Entry(HandlerContext c)
    {
        var l = c.Layout;
        yield return JumpIf("No request waiting", "STEP = 0: the port is receiving or sending; nothing to do in this scan.",
            EndOfSlice, Op("LDB=", l.B(Step), "0"));
        yield return Always(
            "Go on with the request",
            $"AC0-AC3 as the last slice left them (the program may have used them since); {PassesPerScan} loop passes in this scan.",
            Op("MOVD", l.Dw(Save), "AC0"), Op("MOVD", l.Dw(Save + 4), "AC1"), Op("MOVD", l.Dw(Save + 8), "AC2"),
            Op("MOVD", l.Dw(Save + 12), "AC3"), Op("MOVB", Dec(PassesPerScan), l.B(Budget)));
        foreach (var (step, label) in Resumes.Concat(ChangesPart.Resumes(c)).Concat(ChangesOfListsPart.Resumes))
        {
            yield return JumpIf($"STEP {step}", $"Go on at label {label}.", label, Op("LDB=", l.B(Step), Dec(step)));
        }
    }

    /// <summary>Ends this scan's slice; the next scan goes on at <paramref name="step"/>.</summary>
    public static StlNetwork Pause(HandlerContext c, string title, int step) =>
        Always(title, $"Enough for one scan: the next scan goes on at STEP {step}.",
            Op("MOVB", Dec(step), c.Layout.B(Step)), Op("JMP", Dec(Yield)));

    /// <summary>The request is done (reply on its way, or silence): nothing left for the next scans.</summary>
    public static (string, string[]) Done(HandlerContext c) => Op("MOVB", "0", c.Layout.B(Step));

    /// <summary>The last networks of OP_PANEL: keep the accumulators, then the end every slice jumps to.</summary>
    public static IEnumerable<StlNetwork> Exit(HandlerContext c)
    {
        var l = c.Layout;
        yield return Label(Yield, "end of this scan's slice");
        yield return Always(
            "Keep the accumulators", "AC0-AC3 to SAVE: the next slice takes them back.",
            Op("MOVD", "AC0", l.Dw(Save)), Op("MOVD", "AC1", l.Dw(Save + 4)), Op("MOVD", "AC2", l.Dw(Save + 8)),
            Op("MOVD", "AC3", l.Dw(Save + 12)));
        yield return Label(EndOfSlice, "back to OB1");
    }

    /// <summary>
    /// A loop over characters in passes of at most <paramref name="perPass"/>, BUDGET passes per scan: AC3 counts the
    /// characters left (the caller sets it), AC0 is the FOR index, <paramref name="perCharacter"/> the loop body. When
    /// the scan's passes are used up the next scan goes on at <paramref name="passStep"/>.
    /// </summary>
    public static IEnumerable<StlNetwork> Passes(
        HandlerContext c, string what, int perPass, int passLabel, int passStep, IEnumerable<StlNetwork> perCharacter)
    {
        var l = c.Layout;
        yield return Label(passLabel, $"one pass of the {what}");
        yield return Always($"Pass of the {what}", $"CHUNK = characters left, at most {perPass}; one loop pass used.",
            Op("MOVW", "AC3", l.W(Chunk)), Op("DECB", l.B(Budget)));
        yield return new NetworkBuilder("At most one pass worth", $"CHUNK = {perPass} when more characters are left.")
            .Op("LDW>", l.W(Chunk), Dec(perPass)).Op("MOVW", Dec(perPass), l.W(Chunk)).Build();
        yield return Always($"{what}: CHUNK characters", "AC3 = characters left after this pass; AC0 counts the loop.",
            Op("-I", l.W(Chunk), "AC3"), Op("FOR", "AC0", "1", l.W(Chunk)));
        foreach (var network in perCharacter)
        {
            yield return network;
        }

        yield return new NetworkBuilder($"End of the {what} pass").Op("NEXT").Build();
        yield return JumpIf($"{what}: scan's passes used", "Characters left, no pass left in this scan: the next scan goes on.",
            Yield, Op("LDW>", "AC3", "0"), Op("AB=", l.B(Budget), "0"), Op("MOVB", Dec(passStep), l.B(Step)));
        yield return JumpIf($"{what}: next pass", "Characters left: another pass.", passLabel, Op("LDW>", "AC3", "0"));
    }
}
