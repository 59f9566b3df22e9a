namespace OperatorPanel.Core.Protocol;

/// <summary>
/// The handler's own V bytes, one contiguous range that IDENTIFY reports (V_FIRST, V_BYTES): the 256-byte frame
/// buffer, the work bytes, then the READ CHANGES copies (docs/protocol-v2.md, "Work bytes"). StlGen's HandlerLayout and
/// the reference model both take the sizes from here.
/// </summary>
public static class HandlerMemory
{
    /// <summary>Byte 0 the RCV/XMT count, bytes 1-255 one frame.</summary>
    public const int BufferBytes = 256;

    /// <summary>
    /// v1's 36 work bytes plus 16 for v2: CRC (2), REQCHECK (2), FRAME_START (1), STOP_REQUEST (1), COPY_START1-4 (4),
    /// COPY_VALID1-4 (4), COPY_FREE (1), K (1).
    /// </summary>
    public const int WorkBytes = 36 + 16;

    /// <summary>COPY_BYTES when the generator is not told otherwise: room for the copies of a few typical lists.</summary>
    public const int DefaultCopyBytes = 120;

    /// <summary>The most COPY_BYTES can be: one byte in IDENTIFY.</summary>
    public const int MaxCopyBytes = 255;

    /// <summary>V_BYTES of a handler generated with <paramref name="copyBytes"/> copy bytes.</summary>
    public static int VBytes(int copyBytes) => BufferBytes + WorkBytes + copyBytes;
}
