using OperatorPanel.Simulator.Stl.Freeport;

namespace OperatorPanel.StlGen.Tests.Streaming;

/// <summary>
/// One request served by <see cref="ReplyChunkRig"/>: the characters the handler sent and the reference model's reply,
/// the request's end, every character with its completion time, the end of the scan in which OP_PANEL finished the
/// reply's check, whether the port received again before the reply's '&gt;' had left, and the transmit completes (one
/// per chunk).
/// </summary>
internal sealed record ServedReply(
    string Sent, string Expected, TimeSpan RequestEnd, IReadOnlyList<WireCharacter> Characters, TimeSpan CheckDone, bool ReceivingBeforeEnd,
    int Chunks)
{
    /// <summary>When the reply's first character started on the wire.</summary>
    public TimeSpan FirstCharacterStart(TimeSpan characterTime) => Characters[0].At - characterTime;
}
