using System.Collections.Immutable;

namespace OperatorPanel.Core.Protocol;

/// <summary>
/// Frame = '&lt;' BODY CHECK '&gt;': BODY = uppercase hex pairs of STATION SEQ CMD PAYLOAD, CHECK = the body's
/// <see cref="FrameCheck"/> as four <see cref="CheckCharacters"/> (docs/protocol-v2.md, "Frame grammar").
/// Pure functions: no state, no I/O.
/// </summary>
public static class FrameCodec
{
    /// <summary>'&lt;' = 16#3C: SMB88, the RCV start character. Never a hex digit or check character.</summary>
    public const byte StartChar = (byte)'<';

    /// <summary>'&gt;' = 16#3E: SMB89, the RCV end character.</summary>
    public const byte EndChar = (byte)'>';

    /// <summary>Station, sequence and command as hex pairs.</summary>
    public const int MinBodyChars = 2 * FreeportFrame.OverheadBytes;

    /// <summary>'&lt;', the four check characters and '&gt;': the characters of a frame besides its body.</summary>
    public const int OverheadChars = 2 + CheckCharacters.Count;

    /// <summary>The characters of <paramref name="frame"/> as sent, '&lt;' to '&gt;'.</summary>
    /// <exception cref="ArgumentException">The frame would exceed 255 characters (one XMT buffer).</exception>
    public static byte[] Encode(FreeportFrame frame)
    {
        ArgumentNullException.ThrowIfNull(frame);
        var chars = ProtocolLimits.FrameChars(frame.BodyBytes);
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

        CheckCharacters.Write(FrameCheck.Compute(result.AsSpan(1, at - 1)), result.AsSpan(at, CheckCharacters.Count));
        result[^1] = EndChar;
        return result;
    }

    /// <summary>
    /// Checks delimiters, length, hex digits, check characters and the check, in the order of processing order step 2,
    /// and decodes the body.
    /// </summary>
    public static bool TryDecode(ReadOnlySpan<byte> frame, out FreeportFrame decoded, out FrameError error)
    {
        decoded = null!;
        error = Check(frame, out _);
        if (error != FrameError.None)
        {
            return false;
        }

        var body = frame[1..^(CheckCharacters.Count + 1)];
        var bytes = new byte[body.Length / 2];
        for (var i = 0; i < bytes.Length; i++)
        {
            bytes[i] = HexAscii.Pair(body[2 * i], body[(2 * i) + 1]);
        }

        decoded = new FreeportFrame(bytes[0], bytes[1], bytes[2], ImmutableArray.Create(bytes, 3, bytes.Length - 3));
        return true;
    }

    /// <summary>
    /// The check a frame carries, read from its four check characters; false when <paramref name="frame"/> is not a
    /// valid frame. The REQCHECK a reply to this frame must carry.
    /// </summary>
    public static bool TryGetCheck(ReadOnlySpan<byte> frame, out ushort check) => Check(frame, out check) == FrameError.None;

    /// <summary>The check of the body of <paramref name="frame"/> as <see cref="Encode"/> writes it.</summary>
    public static ushort CheckOf(FreeportFrame frame)
    {
        var chars = Encode(frame);
        return FrameCheck.Compute(chars.AsSpan(1, chars.Length - OverheadChars));
    }

    private static FrameError Check(ReadOnlySpan<byte> frame, out ushort check)
    {
        check = 0;
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

        if (frame.Length < MinBodyChars + OverheadChars)
        {
            return FrameError.TooShort;
        }

        var body = frame[1..^(CheckCharacters.Count + 1)];
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

        if (!CheckCharacters.TryRead(frame[^(CheckCharacters.Count + 1)..^1], out check))
        {
            return FrameError.BadCheckCharacter;
        }

        return FrameCheck.Compute(body) == check ? FrameError.None : FrameError.ChecksumMismatch;
    }

    private static int Put(byte[] target, int at, byte value)
    {
        target[at] = HexAscii.High(value);
        target[at + 1] = HexAscii.Low(value);
        return at + 2;
    }
}
