using System.Collections.Immutable;

namespace OperatorPanel.Core.Protocol.V3;

/// <summary>
/// A v3 reply: '&lt;' LEN STATUS REQCHECK PAYLOAD CHECK. <see cref="RequestCheck"/> is the B part (the last 2 check
/// bytes) of the request it answers; an error reply has no payload.
/// </summary>
public sealed record Reply(ReplyStatus Status, ushort RequestCheck, ImmutableArray<byte> Payload)
{
    public bool Equals(Reply? other) =>
        other is not null && Status == other.Status && RequestCheck == other.RequestCheck && Payload.AsSpan().SequenceEqual(other.Payload.AsSpan());

    public override int GetHashCode() => HashCode.Combine(Status, RequestCheck, Payload.Length);
}
