namespace OperatorPanel.Core.Polling;

/// <summary>
/// Where some bytes of a watched value travel: <paramref name="Length"/> bytes from <paramref name="DataOffset"/>
/// of the reply to <see cref="PollPlan.Frames"/>[<paramref name="FrameIndex"/>]. A value cut by a 119-byte split
/// has two slices.
/// </summary>
public readonly record struct ReplySlice(int FrameIndex, int DataOffset, int Length);
