using OperatorPanel.Core.Protocol;
using OperatorPanel.StlGen.Model;
using static OperatorPanel.StlGen.Handler.HandlerContext;
using static OperatorPanel.StlGen.Handler.HandlerLayout;
using static OperatorPanel.StlGen.Handler.HandlerSnippets;

namespace OperatorPanel.StlGen.Handler;

/// <summary>
/// The end of the request's work: error codes, the reply frame (header with REQCHECK, count, check characters, '&gt;')
/// over the request, the reply delay by timed interrupt 0, and silence (docs/protocol-v2.md section 6, steps 5-6).
/// </summary>
internal static class ReplyPart
{
    /// <summary>
    /// The codes the handler answers with (every one but None, and BadChecksum, which is never answered), in code order;
    /// a new ProtocolError gets its label and network here without a change.
    /// </summary>
    private static readonly ProtocolError[] ErrorReplies =
        [.. Enum.GetValues<ProtocolError>().Where(error => error is not (ProtocolError.None or ProtocolError.BadChecksum))];

    /// <summary>
    /// Buffer byte of the reply's first payload character: '&lt;', STATION, SEQ, CMD, STATUS and REQCHECK (2 bytes) before it.
    /// </summary>
    public const int PayloadStart = 2 + (2 * ProtocolLimits.ReplyHeaderBytes);

    public static IEnumerable<StlNetwork> Networks(HandlerContext c)
    {
        var l = c.Layout;
        foreach (var error in ErrorReplies)
        {
            yield return Label(HandlerLabels.Error(error), $"error {Digits(error)}");
            yield return Always($"Error {Digits(error)}", "STATUS = error code; the reply has no payload.",
                Op("MOVB", Hex((byte)error), l.B(List)), Op("JMP", Dec(HandlerLabels.ErrorReply)));
        }

        yield return Label(HandlerLabels.ErrorReply, "error reply");
        yield return Always("Error reply", $"No payload: the check characters go to buffer byte {PayloadStart}.", Op("MOVD", l.Ptr(PayloadStart), "AC1"));
        yield return Label(HandlerLabels.Finish, "finish the reply");
        yield return new NetworkBuilder(
                "Reply: header and count",
                $"CMD | {Hex(FreeportFrame.ReplyBit)}, STATUS and REQCHECK as characters 6-13 (STATION, SEQ stay as received);",
                $"AC1 = the first check character; count = AC1 - buffer start + {CheckCharacters.Count}, the '>' last.")
            .Op("LD", "SM0.0").Op("ORB", Hex(FreeportFrame.ReplyBit), l.B(Cmd)).Op("HTA", l.B(Cmd), l.B(6), "8").Op("MOVD", l.Ptr(0), "AC2")
            .Op("MOVD", "AC1", "AC0").Op("-D", "AC2", "AC0").Op("+D", Dec(CheckCharacters.Count), "AC0").Op("MOVB", "AC0", l.B(0)).Build();
        yield return new NetworkBuilder(
                "Reply: would it reach the stored lists?",
                "A reply longer than LAST_FREE overwrites stored descriptors: forget every list (invalidation 3).")
            .Op("LDB>", l.B(0), l.B(LastFree)).ClearLists(l).Build();
        yield return SlicePart.Pause(c, "Reply built", SlicePart.StepReplyCheck);
        yield return Label(SlicePart.ReplyCheck, "frame check of the reply");
        foreach (var network in FrameCheckPart.Reply(c))
        {
            yield return network;
        }

        foreach (var network in ChunkPart.AfterPass(c))
        {
            yield return network;
        }

        yield return Label(HandlerLabels.Silence, "no reply");
        yield return Always(
            "No reply: receive again", "Silence: the port listens for the next frame at once.",
            Op("RCV", l.B(0), c.PortOperand), SlicePart.Done(c), Op("JMP", Dec(SlicePart.EndOfSlice)));
    }
}
