using OperatorPanel.Core.Protocol;

namespace OperatorPanel.TestKit.ProtocolDoc;

/// <summary>
/// One step of docs/protocol.md section 5, in document order: memory the text sets ("MB1 := 40"), or a request with the
/// reply the text gives (null: "silence").
/// </summary>
/// <param name="Line">The text it came from, for messages.</param>
/// <param name="Pokes">Bytes the text sets before the next request.</param>
/// <param name="Request">The request frame; null for a step that only sets memory.</param>
/// <param name="Reply">The reply the text shows; null for silence.</param>
/// <param name="Corrupted">The text calls the request corrupted (a bit flipped): its check must fail.</param>
/// <param name="OtherHandler">The text sends it to another handler than the section's (the compact one).</param>
public sealed record Section5Step(
    string Line,
    IReadOnlyList<(ProtocolArea Area, int Offset, byte Value)> Pokes,
    byte[]? Request,
    byte[]? Reply,
    bool Corrupted,
    bool OtherHandler);
