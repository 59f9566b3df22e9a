namespace OperatorPanel.Core.Protocol;

/// <summary>Sizes that follow from the S7-200's 255-character RCV/XMT buffers (docs/protocol.md, "Limits").</summary>
public static class ProtocolLimits
{
    /// <summary>Longest frame, '&lt;' and '&gt;' included: one RCV or XMT buffer.</summary>
    public const int MaxFrameChars = 255;

    /// <summary>Longest body in bytes: (255 - 2) characters, rounded down to whole hex pairs.</summary>
    public const int MaxBodyBytes = 126;

    /// <summary>Items in one READ request; the handler keeps their descriptors in 32 bytes of L memory.</summary>
    public const int MaxReadItems = 8;

    /// <summary>Data bytes in one READ reply: 126 - station, sequence, command, status, block check.</summary>
    public const int MaxReadData = 121;

    /// <summary>Data bytes in one WRITE request: 126 - station, sequence, command, area, offset (2), length, block check.</summary>
    public const int MaxWriteData = 118;
}
