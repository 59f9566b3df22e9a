using System.Collections.Immutable;

namespace OperatorPanel.Core.Protocol;

/// <summary>
/// Frame = '&lt;' BODY '&gt;', BODY = uppercase hex pairs of STATION SEQ CMD PAYLOAD, then the block check as two hex
/// digits (docs/protocol.md, "Frame grammar"). Pure functions: no state, no I/O.
/// </summary>
public static class FrameCodec
{
    /// <summary>'&lt;' = 16#3C: SMB88, the RCV start character. Never a hex digit, so data cannot fake it.</summary>
    public const byte StartChar = (byte)'<';

    /// <summary>'&gt;' = 16#3E: SMB89, the RCV end character.</summary>
    public const byte EndChar = (byte)'>';

    /// <summary>Station, sequence, command and block check as hex pairs.</summary>
    public const int MinBodyChars = 2 * FreeportFrame.OverheadBytes;

    /// <summary>The characters of <paramref name="frame"/> as sent, '&lt;' to '&gt;'.</summary>
    /// <exception cref="ArgumentException">The frame would exceed 255 characters (one XMT buffer).</exception>
    public static byte[] Encode(FreeportFrame frame)
    {
        ArgumentNullException.ThrowIfNull(frame);
        var chars = 2 + (2 * frame.BodyBytes);
        if (chars > ProtocolLimits.MaxFrameChars)
        {
            throw new ArgumentException($"a frame with {frame.Payload.Length} payload bytes needs {chars} characters; the limit is {ProtocolLimits.MaxFrameChars}", nameof(frame));
        }

        var result = new byte[chars];
        result[0] = StartChar;
        var at = 1;
        Span<byte> head = [frame.Station, frame.Sequence, frame.Command];
        foreach (var value in head)
        {
            at = Put(result, at, value);
        }

        foreach (var value in frame.Payload)
        {
            at = Put(result, at, value);
        }

        at = Put(result, at, BlockCheck.Compute(result.AsSpan(1, at - 1)));
        result[at] = EndChar;
        return result;
    }

    /// <summary>
    /// Checks delimiters, length, hex digits and block check, in the order the PLC does (processing order step 2),
    /// and decodes the body.
    /// </summary>
    public static bool TryDecode(ReadOnlySpan<byte> frame, out FreeportFrame decoded, out FrameError error)
    {
        decoded = null!;
        error = Check(frame);
        if (error != FrameError.None)
        {
            return false;
        }

        var body = frame[1..^1];
        var bytes = new byte[body.Length / 2];
        for (var i = 0; i < bytes.Length; i++)
        {
            bytes[i] = HexAscii.Pair(body[2 * i], body[(2 * i) + 1]);
        }

        decoded = new FreeportFrame(bytes[0], bytes[1], bytes[2], ImmutableArray.Create(bytes, 3, bytes.Length - 4));
        return true;
    }

    private static FrameError Check(ReadOnlySpan<byte> frame)
    {
        if (frame.Length > ProtocolLimits.MaxFrameChars)
        {
            return FrameError.TooLong;
        }

        if (frame.Length == 0 || frame[0] != StartChar)
        {
            return FrameError.BadStart;
        }

        if (frame.Length < 2 || frame[^1] != EndChar)
        {
            return FrameError.BadEnd;
        }

        var body = frame[1..^1];
        if (body.Length < MinBodyChars)
        {
            return FrameError.TooShort;
        }

        if (body.Length % 2 != 0)
        {
            return FrameError.OddLength;
        }

        foreach (var c in body)
        {
            if (!HexAscii.IsDigit(c))
            {
                return FrameError.NotHex;
            }
        }

        var expected = BlockCheck.Compute(body[..^2]);
        return HexAscii.Pair(body[^2], body[^1]) == expected ? FrameError.None : FrameError.ChecksumMismatch;
    }

    private static int Put(byte[] target, int at, byte value)
    {
        target[at] = HexAscii.High(value);
        target[at + 1] = HexAscii.Low(value);
        return at + 2;
    }
}
