namespace OperatorPanel.Core.Link;

/// <summary>Thread-safe counters behind one station's <see cref="LinkStatistics"/>.</summary>
internal sealed class StationStatistics
{
    private readonly Lock _gate = new();
    private long _requests;
    private long _replies;
    private long _retries;
    private long _timeouts;
    private long _corrupt;
    private long _negative;
    private long _corruptedRefusals;
    private TimeSpan _sum;
    private TimeSpan? _min;
    private TimeSpan? _max;

    public void Request() => Add(ref _requests);

    public void Retry() => Add(ref _retries);

    public void Timeout() => Add(ref _timeouts);

    public void Corrupt() => Add(ref _corrupt);

    public void NegativeReply() => Add(ref _negative);

    public void CorruptedRefusal() => Add(ref _corruptedRefusals);

    public void Reply(TimeSpan roundTrip)
    {
        lock (_gate)
        {
            _replies++;
            _sum += roundTrip;
            _min = _min is { } min && min <= roundTrip ? min : roundTrip;
            _max = _max is { } max && max >= roundTrip ? max : roundTrip;
        }
    }

    public LinkStatistics Snapshot()
    {
        lock (_gate)
        {
            TimeSpan? average = _replies == 0 ? null : _sum / _replies;
            return new LinkStatistics(_requests, _replies, _retries, _timeouts, _corrupt, _negative, _min, average, _max)
            {
                CorruptedRefusals = _corruptedRefusals,
            };
        }
    }

    private void Add(ref long counter)
    {
        lock (_gate)
        {
            counter++;
        }
    }
}
