namespace OperatorPanel.Core.Ppi;

/// <summary>
/// One outcome of <see cref="PpiFrameReader"/>: a checked telegram, or the error that ended a broken one (then
/// <see cref="Frame"/> is null). <see cref="SkippedBytes"/> counts the characters dropped since the previous outcome
/// that began no telegram (line noise, or the rest of a broken one).
/// </summary>
public readonly record struct PpiReadResult(PpiFrame? Frame, PpiFrameError Error, int SkippedBytes)
{
    public bool IsFrame => Frame is not null;
}
