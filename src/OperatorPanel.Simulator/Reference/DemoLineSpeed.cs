namespace OperatorPanel.Simulator.Reference;

/// <summary>
/// Bottles per minute over the last minute (LineSpeed VW140), from sixty one-second buckets. During the first minute
/// the bottles so far are scaled up to a minute, so the figure means something from the first bottle on.
/// </summary>
internal sealed class DemoLineSpeed
{
    private readonly int[] _perSecond = new int[60];
    private long _second;

    public void Count(long ms)
    {
        Roll(ms);
        _perSecond[_second % 60]++;
    }

    public ushort BottlesPerMinute(long ms)
    {
        Roll(ms);
        var window = Math.Clamp(ms, 1_000, 60_000);
        return (ushort)(_perSecond.Sum() * 60_000L / window);
    }

    private void Roll(long ms)
    {
        while (_second < ms / 1000)
        {
            _second++;
            _perSecond[_second % 60] = 0;
        }
    }
}
