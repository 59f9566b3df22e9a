namespace OperatorPanel.Simulator.Stl.Freeport;

/// <summary>
/// The PC side's transmitter: characters handed over while earlier ones are still on the line follow them back to
/// back (one character time apart, on the same time base, so no rounding accumulates); otherwise a new burst starts.
/// </summary>
internal sealed class WireSender
{
    private WireBurst? _last;

    public WireSender(LineSettings settings) => Settings = settings;

    public LineSettings Settings { get; }

    /// <summary>Sends <paramref name="characters"/> from <paramref name="at"/>; returns the burst receivers must see.</summary>
    public WireBurst Send(ReadOnlySpan<byte> characters, TimeSpan at)
    {
        if (_last is { IsBreak: false } last && last.End > at)
        {
            last.Append(characters);
            return last;
        }

        _last = new WireBurst(Later(at), Settings, isBreak: false);
        _last.Append(characters);
        return _last;
    }

    public WireBurst SendBreak(TimeSpan at)
    {
        _last = new WireBurst(Later(at), Settings, isBreak: true);
        return _last;
    }

    private TimeSpan Later(TimeSpan at) => _last is null || _last.End <= at ? at : _last.End;
}
