using System.Buffers.Binary;
using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Core.Protocol.V3;

/// <summary>
/// Encodes and decodes v3 frames (docs/protocol.md section 1): '&lt;' LEN BODY CHECK with LEN the number of bytes of
/// it. Pure functions: no state, no I/O. The PC encodes requests and decodes replies; the reference model does the
/// opposite, so both directions are here.
/// </summary>
public static class Codec
{
    /// <summary>'&lt;' LEN STATION SEQCMD, then the check: LEN of the shortest request.</summary>
    public const int MinRequestLen = Limits.RequestHead + WordCheck.Bytes;

    /// <summary>'&lt;' LEN STATUS REQCHECK, then the check: LEN of the shortest reply.</summary>
    public const int MinReplyLen = Limits.ReplyHead + WordCheck.Bytes;

    /// <exception cref="ArgumentException">The frame would exceed 255 bytes.</exception>
    public static byte[] Encode(Request request)
    {
        ArgumentNullException.ThrowIfNull(request);
        ArgumentOutOfRangeException.ThrowIfGreaterThanOrEqual(request.Sequence, Limits.SequenceCount);
        return Frame([(byte)request.Station.Address, request.SequenceAndCommand], request.Payload.AsSpan());
    }

    /// <exception cref="ArgumentException">The frame would exceed 255 bytes.</exception>
    public static byte[] Encode(Reply reply)
    {
        ArgumentNullException.ThrowIfNull(reply);
        return Frame([(byte)reply.Status, (byte)(reply.RequestCheck >> 8), (byte)reply.RequestCheck], reply.Payload.AsSpan());
    }

    /// <summary>REQCHECK for a reply to <paramref name="frame"/>: its last 2 bytes, the B part of its check.</summary>
    public static ushort RequestCheckOf(ReadOnlySpan<byte> frame) => BinaryPrimitives.ReadUInt16BigEndian(frame[^2..]);

    /// <summary>A request as a station receives it: '&lt;', LEN = its length, the check, STATION 1-126, CMD not 0.</summary>
    public static bool TryDecodeRequest(ReadOnlySpan<byte> frame, out Request request, out DecodeError error)
    {
        request = null!;
        error = Validate(frame, MinRequestLen);
        if (error == DecodeError.None && (frame[2] is 0 or > 126 || (frame[3] & 0x0F) == 0))
        {
            error = DecodeError.BadHeader;
        }

        if (error != DecodeError.None)
        {
            return false;
        }

        request = new Request(new Station(frame[2]), (byte)(frame[3] >> 4), (Command)(frame[3] & 0x0F), Body(frame, Limits.RequestHead));
        return true;
    }

    /// <summary>A reply as the PC receives it: '&lt;', LEN = its length, the check, STATUS with bit 7.</summary>
    public static bool TryDecodeReply(ReadOnlySpan<byte> frame, out Reply reply, out DecodeError error)
    {
        reply = null!;
        error = Validate(frame, MinReplyLen);
        if (error == DecodeError.None && frame[2] < 0x80)
        {
            error = DecodeError.BadHeader;
        }

        if (error != DecodeError.None)
        {
            return false;
        }

        reply = new Reply((ReplyStatus)frame[2], BinaryPrimitives.ReadUInt16BigEndian(frame[3..]), Body(frame, Limits.ReplyHead));
        return true;
    }

    /// <summary>
    /// <see cref="TryDecodeReply"/>, and the reply answers <paramref name="request"/> (the encoded frame sent): its
    /// REQCHECK is that frame's; an error reply has no payload.
    /// </summary>
    public static bool TryDecodeReplyTo(ReadOnlySpan<byte> frame, ReadOnlySpan<byte> request, out Reply reply, out DecodeError error)
    {
        if (!TryDecodeReply(frame, out reply, out error))
        {
            return false;
        }

        error = reply.RequestCheck != RequestCheckOf(request) ? DecodeError.RequestCheckMismatch
            : reply.Status.IsError() && reply.Payload.Length != 0 ? DecodeError.BadPayload
            : DecodeError.None;
        return error == DecodeError.None;
    }

    private static byte[] Frame(ReadOnlySpan<byte> head, ReadOnlySpan<byte> payload)
    {
        var length = 2 + head.Length + payload.Length + WordCheck.Bytes;
        if (length > Limits.MaxFrameBytes)
        {
            throw new ArgumentException($"a frame with {payload.Length} payload bytes needs {length} bytes; the limit is {Limits.MaxFrameBytes}", nameof(payload));
        }

        var frame = new byte[length];
        frame[0] = Limits.Start;
        frame[1] = (byte)Limits.LenOf(length);
        head.CopyTo(frame.AsSpan(2));
        payload.CopyTo(frame.AsSpan(2 + head.Length));
        WordCheck.Write(frame.AsSpan(0, length - WordCheck.Bytes), frame.AsSpan(length - WordCheck.Bytes));
        return frame;
    }

    private static DecodeError Validate(ReadOnlySpan<byte> frame, int minLen)
    {
        if (frame.Length == 0 || frame[0] != Limits.Start)
        {
            return DecodeError.BadStart;
        }

        if (frame.Length > Limits.MaxFrameBytes || frame.Length < minLen || frame[1] != frame.Length)
        {
            return DecodeError.BadLength;
        }

        return WordCheck.Matches(frame) ? DecodeError.None : DecodeError.CheckMismatch;
    }

    private static ImmutableArray<byte> Body(ReadOnlySpan<byte> frame, int head) => [.. frame[head..^WordCheck.Bytes]];
}
