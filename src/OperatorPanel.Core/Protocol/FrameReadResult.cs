using System.Collections.Immutable;

namespace OperatorPanel.Core.Protocol;

/// <summary>
/// One outcome of <see cref="FrameReader"/>: the characters of a frame ('&lt;' to '&gt;', not yet checked; decode
/// them with <see cref="FrameCodec"/> or <see cref="ResponseCodec"/>), or <see cref="FrameError.TooLong"/> with no
/// characters. <paramref name="SkippedBytes"/> counts the noise dropped since the previous outcome: bytes before a
/// '&lt;' and partial frames abandoned for a new '&lt;'.
/// </summary>
public readonly record struct FrameReadResult(ImmutableArray<byte> Frame, FrameError Error, int SkippedBytes)
{
    public bool IsFrame => Error == FrameError.None;
}
