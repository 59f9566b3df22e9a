namespace OperatorPanel.Core.Protocol.V3;

/// <summary>The sizes of protocol v3 frames (docs/protocol.md section 1).</summary>
public static class Limits
{
    /// <summary>'&lt;' = 16#3C: the first byte of every frame, SMB88, the RCV start character.</summary>
    public const byte Start = (byte)'<';

    /// <summary>One XMT or RCV holds at most 255 characters; LEN (the frame's bytes, '&lt;' to the check) is then at most 255.</summary>
    public const int MaxFrameBytes = 255;

    /// <summary>'&lt;' LEN STATION SEQCMD: the bytes of a request before its payload.</summary>
    public const int RequestHead = 4;

    /// <summary>'&lt;' LEN STATUS REQCHECK (2): the bytes of a reply before its payload.</summary>
    public const int ReplyHead = 5;

    /// <summary>A request of <paramref name="payloadBytes"/>: head, payload and the 4 check bytes.</summary>
    public static int RequestBytes(int payloadBytes) => RequestHead + payloadBytes + WordCheck.Bytes;

    /// <summary>A reply of <paramref name="payloadBytes"/>: head, payload and the 4 check bytes.</summary>
    public static int ReplyBytes(int payloadBytes) => ReplyHead + payloadBytes + WordCheck.Bytes;

    /// <summary>LEN of a frame of <paramref name="frameBytes"/>: every byte of it, '&lt;' and LEN included.</summary>
    public static int LenOf(int frameBytes) => frameBytes;

    /// <summary>SEQ runs 0-15 (the high 4 bits of SEQCMD).</summary>
    public const int SequenceCount = 16;

    /// <summary>One CHANGES entry: INDEX (the double word's number in the list data) and its 4 bytes.</summary>
    public const int ChangeEntryBytes = 5;
}
