using System.Collections.Immutable;

namespace OperatorPanel.Core.Protocol;

/// <summary>
/// One decoded frame body, its check characters aside: STATION SEQ CMD PAYLOAD. For a reply, CMD has bit 7 set and
/// the payload starts with STATUS and REQCHECK (2 bytes) (docs/protocol-v2.md, "Frame").
/// </summary>
public sealed record FreeportFrame(byte Station, byte Sequence, byte Command, ImmutableArray<byte> Payload)
{
    /// <summary>Bit 7 of CMD marks a reply, so a station never mistakes an overheard reply for a request.</summary>
    public const byte ReplyBit = 0x80;

    /// <summary>Station, sequence and command: the bytes every body has besides its payload.</summary>
    public const int OverheadBytes = 3;

    public bool IsReply => (Command & ReplyBit) != 0;

    /// <summary>Body length in bytes (the check characters are not body).</summary>
    public int BodyBytes => OverheadBytes + Payload.Length;

    public bool Equals(FreeportFrame? other) =>
        other is not null
        && Station == other.Station
        && Sequence == other.Sequence
        && Command == other.Command
        && Payload.AsSpan().SequenceEqual(other.Payload.AsSpan());

    public override int GetHashCode() => HashCode.Combine(Station, Sequence, Command, Payload.Length);

    public override string ToString() =>
        $"FreeportFrame {{ Station = {Station:X2}, Sequence = {Sequence:X2}, Command = {Command:X2}, Payload = {Convert.ToHexString(Payload.AsSpan())} }}";
}
