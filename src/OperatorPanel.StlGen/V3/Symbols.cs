using System.Globalization;
using OperatorPanel.StlGen.Emit;

namespace OperatorPanel.StlGen.V3;

/// <summary>The v3 handler's V bytes as Micro/WIN symbol table rows (Symbol TAB Address TAB Comment).</summary>
internal static class Symbols
{
    public static string Write(Layout l)
    {
        var w = new LineWriter();
        foreach (var (symbol, address, comment) in Rows(l))
        {
            w.Line($"{symbol}\t{address}\t{comment}");
        }

        return w.ToString();
    }

    private static IEnumerable<(string, string, string)> Rows(Layout l)
    {
        string Count(int n) => n.ToString(CultureInfo.InvariantCulture);
        yield return ("OP_BUF", l.B(0), $"Panel handler v3: request and reply buffer, {Count(l.Shape.RequestBytes + 1)} bytes (byte 0 = character count)");
        yield return ("OP_STEP", l.W(l.Step), "Panel handler: one bit per phase, where OP_PANEL goes on in the next scan (0 = no request)");
        yield return ("OP_FLAGS", l.B(l.Flags), "Panel handler: bit 0 transmitter owned, 2 STOP now, 3 copy valid, 7 SM0.7 last scan");
        yield return ("OP_CMD", l.B(l.Cmd), "Panel handler: command of the request");
        yield return ("OP_STATUS", l.B(l.Status), "Panel handler: status of the reply (INDEX while CHANGES are counted)");
        yield return ("OP_SUM_A", l.Dw(l.SumA), "Panel handler: frame check, XOR sum");
        yield return ("OP_SUM_B", l.W(l.SumB), "Panel handler: frame check, Horner sum");
        yield return ("OP_RXCHECK", l.Dw(l.Rx), "Panel handler: the request's check as received (last word = REQCHECK)");
        yield return ("OP_COUNT", l.B(l.Count), "Panel handler: the quarter of the list the comparison goes on from");
        yield return ("OP_WALK", l.Dw(l.Walk), "Panel handler: pointer of the loop in progress");
        yield return ("OP_END", l.Dw(l.End), "Panel handler: where that loop ends");
        if (l.Shape.HasList)
        {
            // Only the full handler sends in chunks (Context.SendsInChunks); the compact handler leaves these 8 bytes unused.
            yield return ("OP_COVERED", l.Dw(l.Covered), "Panel handler: pointer to the last reply byte ready to send");
            yield return ("OP_SENT", l.Dw(l.Sent), "Panel handler: pointer to the last reply byte handed to XMT");
        }

        yield return ("OP_LAST", l.Dw(l.Last), "Panel handler: pointer to the reply's last byte");
        yield return ("OP_TEMP", l.Dw(l.Temp), "Panel handler: payload length and item length");
        if (!l.Shape.HasList)
        {
            yield break;
        }

        yield return ("OP_N", l.B(l.N), "Panel handler: slots of the list (0 = no list)");
        yield return ("OP_D", l.B(l.D), "Panel handler: data bytes of the list");
        yield return ("OP_USED", l.B(l.Used), "Panel handler: bit g set when group g of 8 slots is in the list");
        yield return ("OP_TAIL", l.Dw(l.Tail), "Panel handler: pointer past a whole list's data in the buffer");
        yield return ("OP_NEXT_SLOT", l.Dw(l.NextSlot), "Panel handler: pointer to the slot DEFINE LIST stores next");
        yield return ("OP_COPY", l.B(l.C), $"Panel handler: the list's copy, {Count(l.Shape.CopyBytes)} bytes, slot k's 4-byte window at 4k");
        yield return ("OP_SLOTS", l.B(l.Slots), $"Panel handler: {Count(l.Shape.ListItems)} slots of 9 bytes: destination pointer, source pointer, length");
    }
}
