using OperatorPanel.Core.Protocol;
using OperatorPanel.StlGen.Model;
using static OperatorPanel.StlGen.Handler.HandlerContext;
using static OperatorPanel.StlGen.Handler.HandlerLayout;
using static OperatorPanel.StlGen.Handler.HandlerSnippets;

namespace OperatorPanel.StlGen.Handler;

/// <summary>
/// The v2 frame check in STL (docs/protocol-v2.md, "Frame check"): CRC-16/MCRF4XX over the body characters, one
/// character at a time without a table (Core's <see cref="FrameCheck.Update"/>, avr-libc _crc_ccitt_update):
/// d = c XOR low8(crc); d = d XOR (d &lt;&lt; 4) in 8 bits; crc = ((d &lt;&lt; 8) OR high8(crc)) XOR (d &gt;&gt; 4) XOR (d &lt;&lt; 3).
/// In STL that is 10 byte and word instructions on the CRC word and a scratch word; a nibble table would take 14 per
/// character and 32 V bytes more. The request's walk also finds the last '&lt;' (the frame starts there: earlier
/// characters are the remains of a frame cut off by noise) and starts the CRC again at it.
/// </summary>
internal static class FrameCheckPart
{
    /// <summary>Characters per scan of the request's CRC walk: 12 keep a scan's slice under 10 ms at ~0.62 ms per character.</summary>
    public const int RequestCharactersPerPass = 12;

    /// <summary>Character pairs per scan of the reply's CRC walk (~1.06 ms each, no '&lt;' to look for, one loop pass per pair).</summary>
    public const int ReplyPairsPerPass = 7;

    /// <summary>Characters per scan when a frame after a cut-off remnant is moved to buffer byte 1 (~0.2 ms each).</summary>
    public const int MovedPerPass = 30;

    /// <summary>Label after the move (or none): the frame starts at buffer byte 1.</summary>
    public const int FrameInPlace = 79;

    private const byte FrameStart = (byte)'<';

    /// <summary>Body characters of the shortest frame: STATION SEQ CMD as hex pairs.</summary>
    private const int MinBodyChars = 2 * FreeportFrame.OverheadBytes;

    /// <summary>'&lt;', the check characters and '&gt;': the characters of a frame besides its body.</summary>
    private const int FrameChars = 2 + CheckCharacters.Count;

    /// <summary>
    /// The request from buffer byte 1 to the count: CRC over bytes 2 .. count-5 in passes, restarted at every '&lt;'
    /// (AC2 keeps where the last one is); then the body length from that '&lt;', the 4 check characters against the
    /// CRC, REQCHECK = CRC, and the frame moved down to byte 1 when it started later. Every failure is silence.
    /// </summary>
    public static IEnumerable<StlNetwork> Request(HandlerContext c)
    {
        var l = c.Layout;
        const int silence = HandlerLabels.Silence;
        yield return Label(SlicePart.RequestStart, "a request received");
        yield return JumpIf(
            "Request: shortest frame", $"Fewer than {MinBodyChars + FrameChars} characters hold no frame: silence.",
            silence, Op("LDB<", l.B(0), Dec(MinBodyChars + FrameChars)));
        yield return new NetworkBuilder(
                "Frame check of the request",
                $"CRC = {Hex(FrameCheck.Initial)}; AC1 walks buffer bytes 2 .. count-{CheckCharacters.Count + 1}, the body when the frame starts at byte 1",
                "(count-6 characters); AC2 points at the frame's '<', byte 1 until a later '<' is found.")
            .Op("LD", "SM0.0").Op("MOVW", "16#FFFF", l.W(Crc)).Op("MOVD", l.Ptr(1), "AC1").Op("MOVD", l.Ptr(1), "AC2").Op("BTI", l.B(0), "AC3")
            .Op("-I", Dec(FrameChars), "AC3").Build();
        var perCharacter = new[]
        {
            Character(c, "AC1", "request"),
            new NetworkBuilder("A '<' starts the frame again", "The characters before it are a cut-off frame's: CRC from the start, AC2 here.")
                .Op("LDB=", "*AC1", Hex(FrameStart)).Op("MOVW", "16#FFFF", l.W(Crc)).Op("MOVD", "AC1", "AC2").Build(),
        };
        foreach (var network in SlicePart.Passes(c, "request check", RequestCharactersPerPass, SlicePart.RequestCheckPass, SlicePart.StepRequestCheck, perCharacter))
        {
            yield return network;
        }

        yield return SlicePart.Pause(c, "Request CRC done", SlicePart.StepFrameChecked);
        yield return Label(SlicePart.FrameChecked, "the frame from the last '<'");
        yield return new NetworkBuilder(
                "Request: body length from the last '<'",
                "AC0 = S, the buffer byte of the frame's '<'; AC3 = buffer byte 0's address.",
                $"Scratch word = count - {FrameChars - 1} - S, the body's characters.")
            .Op("LD", "SM0.0").Op("MOVD", l.Ptr(0), "AC3").Op("MOVD", "AC2", "AC0").Op("-D", "AC3", "AC0").Op("BTI", l.B(0), l.W(Scratch))
            .Op("-I", Dec(FrameChars - 1), l.W(Scratch)).Op("-I", "AC0", l.W(Scratch)).Build();
        yield return JumpIf(
            "Request: body of whole hex pairs", $"Silence when the body has fewer than {MinBodyChars} characters or an odd number.",
            silence, Op("LDW<", l.W(Scratch), Dec(MinBodyChars)), Op("O", l.Bit(Scratch + 1, 0)));
        yield return Expected(c, "request");
        yield return Always(
            "Request: where its check characters are", $"AC1 = buffer byte count-{CheckCharacters.Count}.",
            Op("BTI", l.B(0), "AC1"), Op("ITD", "AC1", "AC1"), Op("-D", Dec(CheckCharacters.Count), "AC1"), Op("+D", "AC3", "AC1"));
        yield return JumpIf(
            "Request: check characters",
            "Silence unless the 4 characters are exactly the computed CRC's: that is each in 16#60-16#6F and their nibbles the CRC.",
            silence, Op("LDD<>", l.Dw(Scratch), "*AC1"));
        yield return Always("Request: REQCHECK", "The reply names the request it answers by this CRC.", Op("MOVW", l.W(Crc), l.W(ReqCheck)));
        yield return JumpIf("Request: frame at byte 1", "No cut-off frame before it: nothing to move.", FrameInPlace, Op("LDW=", "AC0", "1"));
        yield return Always(
            "Request: move the frame to byte 1",
            "Its count - S characters after the '<' go to bytes 2 .. (AC2 from, AC1 to), one by one upwards: source and target overlap.",
            Op("MOVD", l.Ptr(1), "AC1"), Op("BTI", l.B(0), "AC3"), Op("-I", "AC0", "AC3"));
        var move = new NetworkBuilder("Move one character", "Both pointers on by one, then the character down.").Op("LD", "SM0.0").Op("INCD", "AC1").Op("INCD", "AC2").Op("MOVB", "*AC2", "*AC1").Build();
        foreach (var network in SlicePart.Passes(c, "frame move", MovedPerPass, SlicePart.MovePass, SlicePart.StepMovePass, [move]))
        {
            yield return network;
        }

        yield return Always(
            "Request: count of the moved frame", "Count = AC1 - buffer byte 0's address, the '>' now last.",
            Op("MOVD", l.Ptr(0), "AC3"), Op("MOVD", "AC1", "AC0"), Op("-D", "AC3", "AC0"), Op("MOVB", "AC0", l.B(0)));
        yield return SlicePart.Pause(c, "Moved frame checked", SlicePart.StepHeader);
        yield return Label(FrameInPlace, "frame at buffer byte 1: its header in this scan (about 1.2 ms spent on the check's end)");
    }

    /// <summary>
    /// The reply's CRC over bytes 2 .. count-5 in passes, two characters per FOR loop pass (AC2 walks, AC3 counts the
    /// pairs left; SENT = buffer byte 0, the first chunk's XMT table), then the 4 check characters after AC2 and the
    /// '&gt;', AC2 on it. Every pass ends at <see cref="ChunkPart.PassCovered"/> with AC2 at the last character covered.
    /// </summary>
    public static IEnumerable<StlNetwork> Reply(HandlerContext c)
    {
        var l = c.Layout;
        yield return new NetworkBuilder(
                "Frame check of the reply",
                $"CRC = {Hex(FrameCheck.Initial)}; AC2 walks buffer bytes 2 .. count-{CheckCharacters.Count + 1}: (count-6) / 2 pairs of characters (a reply's body is hex pairs).",
                "SENT = buffer byte 0: the first chunk's XMT table.")
            .Op("LD", "SM0.0").Op("MOVW", "16#FFFF", l.W(Crc)).Op("MOVD", l.Ptr(1), "AC2").Op("BTI", l.B(0), "AC3").Op("-I", Dec(FrameChars), "AC3")
            .Op("SRW", "AC3", "1").Op("MOVD", l.Ptr(0), l.Dw(Sent)).Build();
        var pair = new[] { Character(c, "AC2", "reply"), Character(c, "AC2", "reply") };
        foreach (var network in SlicePart.Pass(c, "reply check", ReplyPairsPerPass, SlicePart.ReplyCheckPass, pair))
        {
            yield return network;
        }

        yield return JumpIf("Reply check: pairs left", "This pass covers the body up to AC2.", ChunkPart.PassCovered, Op("LDW>", "AC3", "0"));
        yield return Expected(c, "reply");
        yield return Always("Reply: check characters and '>'", "The 4 characters after the body's last (AC2), then the '>', AC2 on it.",
            Op("INCD", "AC2"), Op("MOVD", l.Dw(Scratch), "*AC2"), Op("+D", Dec(CheckCharacters.Count), "AC2"), Op("MOVB", "16#3E", "*AC2"));
    }

    /// <summary>One character into the CRC: the next character at <paramref name="walker"/> (moved on first).</summary>
    private static StlNetwork Character(HandlerContext c, string walker, string what)
    {
        var l = c.Layout;
        return new NetworkBuilder(
                $"CRC of one {what} character",
                "Next character; low byte of CRC = d = character XOR low byte; d = d XOR (d << 4) in 8 bits (scratch byte).",
                "SWAP: CRC = d << 8 OR the old high byte; then CRC XOR (d << 3) and XOR (d >> 4), the latter as (d << 3) >> 7.")
            .Op("LD", "SM0.0").Op("INCD", walker).Op("XORB", "*" + walker, l.B(Crc + 1)).Op("MOVB", l.B(Crc + 1), l.B(Scratch))
            .Op("SLB", l.B(Scratch), "4").Op("XORB", l.B(Scratch), l.B(Crc + 1)).Op("SWAP", l.W(Crc)).Op("BTI", l.B(Crc), l.W(Scratch))
            .Op("SLW", l.W(Scratch), "3").Op("XORW", l.W(Scratch), l.W(Crc)).Op("SRW", l.W(Scratch), "7").Op("XORW", l.W(Scratch), l.W(Crc))
            .Build();
    }

    /// <summary>The 4 check characters of the CRC into the scratch double word: 16#60 + nibble, low nibble first.</summary>
    private static StlNetwork Expected(HandlerContext c, string what)
    {
        var l = c.Layout;
        return Always(
            $"{what}: check characters of the CRC",
            $"Scratch bytes 0-3 = {Hex(CheckCharacters.Base)} + the CRC's nibbles 0, 1, 2, 3 (low byte's low, low byte's high, high byte's low, high byte's high).",
            Op("MOVB", l.B(Crc + 1), l.B(Scratch)), Op("MOVB", l.B(Crc + 1), l.B(Scratch + 1)), Op("MOVB", l.B(Crc), l.B(Scratch + 2)),
            Op("MOVB", l.B(Crc), l.B(Scratch + 3)), Op("SRB", l.B(Scratch + 1), "4"), Op("SRB", l.B(Scratch + 3), "4"),
            Op("ANDD", "16#0F0F0F0F", l.Dw(Scratch)), Op("ORD", "16#60606060", l.Dw(Scratch)));
    }
}
