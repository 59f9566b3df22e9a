using OperatorPanel.Core.Protocol.V3;
using OperatorPanel.StlGen.Model;
using static OperatorPanel.StlGen.Handler.HandlerSnippets;
using static OperatorPanel.StlGen.V3.Context;

namespace OperatorPanel.StlGen.V3;

/// <summary>
/// 02 READ, 03 WRITE, 04 WRITE BITS and the item check they share with DEFINE LIST (docs/protocol.md section 4): the
/// request's item AREA OFFSET LENGTH sits at byte 5; LENGTH 0 -&gt; 84, unknown AREA (SM, 05, included) -&gt; 82, OFFSET + LENGTH past the
/// area -&gt; 82. <see cref="Commands"/> ends in <see cref="Check"/> (WRITE BITS falls through). In: AC2 at AREA, the length in TEMP's second word. Out: AC3 = the item's first byte; on by CMD. The
/// checks run in the dispatch's scan; the data moves in the next (phase Move), the reply in the one after.
/// </summary>
internal static class ItemPart
{
    // No SM: no S7-200 source found says a pointer reaches SM (docs/sources/s7200-facts.md section 13), so the handler
    // builds no &SMB pointer, and an SM item, area 05, is an unknown AREA: 82.
    private static readonly (int Code, string Pointer)[] Areas = [(4, "&VB0"), (3, "&MB0"), (1, "&IB0"), (2, "&QB0")];

    /// <summary>OFFSET's high byte 16#28 or more: OFFSET 10240 or more, past every area of every CPU (and never negative as a word).</summary>
    private const string PastEveryArea = "16#28";

    /// <summary>The item's LENGTH as a byte (BMB's count), the low byte of <see cref="LengthWord"/>, which every caller sets whole.</summary>
    public static string Length(Layout l) => l.B(l.Temp + 3);

    public static string LengthWord(Layout l) => l.W(l.Temp + 2);

    public static IEnumerable<StlNetwork> Check(Context c)
    {
        var l = c.Layout;
        yield return Label(Labels.ItemCheck, "check an item");
        yield return Always("Item: no area yet", "AC0 = 0 area bytes: an unknown AREA is past its area below (LENGTH is at least 1 here).", Op("MOVW", "0", "AC0"));

        // Every area tested, no jump out: a taken or untaken JMP costs 46 us, a box without power flow 1 us, so each
        // area takes the same 0.40 ms (with jumps V took 0.20 ms and SM, the last tried, 0.63 ms: WRITE's dispatch scan
        // passed 2 ms for an SM or Q item).
        foreach (var (code, pointer) in Areas)
        {
            yield return new NetworkBuilder($"Item: area {code}", $"AC3 = {pointer[1..]}, AC0 = the area's bytes.")
                .Op("LDB=", "*AC2", Dec(code)).Op("MOVD", pointer, "AC3").Op("MOVW", Dec(AreaBytes(c, code)), "AC0").Build();
        }

        yield return Always("Item: room for it", "AC0 = area bytes - LENGTH; AC2 on to OFFSET.", Op("-I", LengthWord(l), "AC0"), Op("INCD", "AC2"));
        yield return Refusal.If(l, "Item: past the area", "Unknown AREA (AC0 negative), OFFSET 10240 or more, or OFFSET > area bytes - LENGTH: 82.", ReplyStatus.AddressOutOfRange,
            Op("LDB>=", "*AC2", PastEveryArea), Op("OW>", "*AC2", "AC0"));
        yield return Always("Item: its first byte", "AC3 = area start + OFFSET.", Op("ITD", "*AC2", "AC0"), Op("+D", "AC0", "AC3"));
        if (!c.HasList)
        {
            yield return ReturnIf("Item: the rest next scan", "LAST = the item's first byte; READ's data, or the write checks and the write (phase Move).", Op("LD", "SM0.0"), Op("MOVD", "AC3", l.Dw(l.Last)), l.Go(Phase.Move));
            yield break;
        }

        // DEFINE LIST's item goes on to its slot: the phase is overwritten rather than jumped to (a JMP costs 46 us
        // taken or not, a box without power flow 1 us).
        yield return Always("Item: the rest next scan", "LAST = the item's first byte; READ's data, or the write checks and the write (phase Move).", Op("MOVD", "AC3", l.Dw(l.Last)), l.Go(Phase.Move));
        yield return new NetworkBuilder("Item: DEFINE LIST", "Its slot is stored next scan (phase DefineStore), from LAST.")
            .Op("LDB=", l.B(l.Cmd), Dec(Command.DefineList)).Ops([l.Go(Phase.DefineStore)]).Build();
        yield return ReturnIf("Item: checked", string.Empty, Op("LD", "SM0.0"));
    }

    public static IEnumerable<StlNetwork> Commands(Context c)
    {
        var l = c.Layout;
        yield return Label(Labels.Read, "02 READ");
        yield return Always("READ: LENGTH", "From byte 8 (AC2 is at the item since the dispatch).", Op("BTI", l.B(8), LengthWord(l)));
        yield return Refusal.If(l, "READ: LENGTH 1 to MAX_DATA", $"84.", ReplyStatus.BadLength, Op("LDB=", l.B(8), "0"), Op("OB>", l.B(8), Dec(HandlerShape.MaxData)));
        yield return JumpIf("READ: check the item", string.Empty, Labels.ItemCheck, Op("LD", "SM0.0"));
        yield return Label(Labels.Write, "03 WRITE");
        yield return Always("WRITE: its length", $"AC0 = {Limits.RequestBytes(4)} + LENGTH: the count of a request whose P is 4 + LENGTH.", Op("BTI", l.B(8), LengthWord(l)), Op("MOVW", LengthWord(l), "AC0"), Op("+I", Dec(Limits.RequestBytes(4)), "AC0"));
        yield return Refusal.If(l, "WRITE: P = 4 + LENGTH, LENGTH 1 to MAX_DATA", "84 (AC0's low byte: it wraps only for a LENGTH over 243, refused anyway).", ReplyStatus.BadLength,
            Op("LDB<>", "AC0", l.B(0)), Op("OB=", l.B(8), "0"), Op("OB>", l.B(8), Dec(HandlerShape.MaxData)));
        yield return JumpIf("WRITE: check the item", string.Empty, Labels.ItemCheck, Op("LD", "SM0.0"));
        yield return Label(Labels.WriteBits, "04 WRITE BITS");
        yield return Always("WRITE BITS: check the byte", "A one-byte item; the item check follows.", Op("MOVW", "1", LengthWord(l)));
    }

    /// <summary>Phase Move for WRITE and WRITE BITS, first: 83 for I, areas outside the mask, the handler's V bytes.</summary>
    private static IEnumerable<StlNetwork> Writable(Context c)
    {
        var l = c.Layout;
        yield return JumpIf("Phase Move: READ", "Phase Move, the only one left after the tests above, starts here (no test, no label). READ needs no write checks.", Labels.MoveData, Op("LDB=", l.B(l.Cmd), Dec(Command.Read)));
        var area = l.B(5);
        var locked = new[] { (1, "I"), (2, "Q"), (3, "M"), (4, "V") }.Where(a => !c.MayWrite(a.Item1)).ToList();
        var net = new NetworkBuilder($"Writable: not {string.Join(", ", locked.Select(a => a.Item2))}", "I never, the rest as the write mask says: 83 (an SM item was refused by the item check, 82).");
        foreach (var (code, _) in locked)
        {
            net.Op(code == locked[0].Item1 ? "LDB=" : "OB=", area, Dec(code));
        }

        yield return net.Op("MOVB", Hex(ReplyStatus.NotWritable), l.B(l.Status)).Op("JMP", Dec(Labels.ErrorReply)).Build();
        if (c.MayWrite(4))
        {
            yield return Always("Writable: past the last byte", "AC1 = OFFSET + LENGTH.", Op("MOVW", l.W(6), "AC1"), Op("+I", LengthWord(l), "AC1"));
            yield return Refusal.If(l, "Writable: not the handler's own V bytes", $"VB{l.First}-VB{l.LastByte}: a block touching them is refused whole, 83.",
                ReplyStatus.NotWritable, Op("LDB=", area, "4"), Op("AW<=", l.W(6), Dec(l.LastByte)), Op("AW>", "AC1", Dec(l.First)));
        }

        yield return Label(Labels.MoveData, "the data");
    }

    /// <summary>Phase Move (its networks follow OP_PANEL's phase tests, no label): the write checks; WRITE's data, READ's data or WRITE's read-back, or WRITE BITS' AND/OR; then phase Reply.</summary>
    public static IEnumerable<StlNetwork> Move(Context c)
    {
        var l = c.Layout;
        var target = "*" + l.Dw(l.Last);
        foreach (var network in Writable(c))
        {
            yield return network;
        }

        yield return new NetworkBuilder("WRITE: the data", "BMB the data (byte 9 on) to the target.")
            .Op("LDB=", l.B(l.Cmd), Dec(Command.Write)).Op("BMB", l.B(9), target, Length(l)).Build();
        yield return DispatchPart.ToReply(c, "READ, WRITE: the data", "BMB the target to the reply's payload (byte 6); P = LENGTH.",
            Op("LDB<>", l.B(l.Cmd), Dec(Command.WriteBits)), Op("BMB", target, l.B(6), Length(l)), Op("BTI", Length(l), l.W(l.Temp)));
        // One store into the target, old XOR ((old XOR VALUE) AND MASK): an AND then an OR stored twice, and a bit set
        // over a set bit was 0 between the two for an interrupt routine of the user's program (found by the soak's judge).
        yield return DispatchPart.ToReply(c, "WRITE BITS: one store, read back", "The byte XOR ((byte XOR VALUE) AND MASK), stored once; the whole byte back; P = 1.",
            Op("LD", "SM0.0"), Op("MOVB", target, "AC0"), Op("XORB", l.B(9), "AC0"), Op("ANDB", l.B(8), "AC0"),
            Op("XORB", "AC0", target), Op("MOVB", target, l.B(6)), Op("MOVW", "1", l.W(l.Temp)));
    }

    private static int AreaBytes(Context c, int code) => code switch
    {
        4 => c.VBytes,
        3 => Bytes(c, Core.Addressing.MemoryArea.M),
        1 => Bytes(c, Core.Addressing.MemoryArea.I),
        _ => Bytes(c, Core.Addressing.MemoryArea.Q),
    };

    private static int Bytes(Context c, Core.Addressing.MemoryArea area) => c.Options.Cpu.TryGetArea(area, out var a) ? a.ByteCount : 0;
}
