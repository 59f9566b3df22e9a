namespace OperatorPanel.Cli.Bench;

/// <summary>
/// What the PLC takes for one request, in simulated time on a line whose own program takes the model's time per scan:
/// <paramref name="UntilFirstReply"/> from the request's '&gt;' to the start of the reply's first character (the
/// receive, the handler's slices up to the first pass of the reply's check, each scan with the user's program, and the
/// reply delay), and <paramref name="ReplyOnBus"/> from that start to the end of the reply's '&gt;', with the pauses
/// between its chunks while the handler still computes its check. <paramref name="Scans"/>: the scans the handler
/// worked on the request (to the last pass of the reply's check), which the link's reply timeout must allow.
/// <paramref name="Source"/> says where the figures come from: the generated handler run in the interpreter, or
/// Core's documented bound when the handler could not be run for this request.
/// </summary>
internal sealed record HandlerCost(int Scans, TimeSpan UntilFirstReply, TimeSpan ReplyOnBus, string Source)
{
    /// <summary>The pauses of the reply on the bus: its time there beyond <paramref name="replyChars"/> character times.</summary>
    public TimeSpan Pauses(int replyChars, TimeSpan characterTime) =>
        ReplyOnBus > characterTime * replyChars ? ReplyOnBus - (characterTime * replyChars) : TimeSpan.Zero;
}
