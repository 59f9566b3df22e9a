namespace OperatorPanel.Core.Link;

/// <summary>
/// One request in flight per RS-485 bus: the bus is half-duplex and every station hears every frame, so a second
/// request before the first reply (or its timeout) would collide. The S7NetPlus TaskQueue idea, as a turn token.
/// </summary>
public sealed class BusArbiter : IDisposable
{
    private readonly SemaphoreSlim _turn = new(1, 1);

    /// <summary>Waits for the bus; dispose the returned token to hand it on.</summary>
    public async Task<IDisposable> AcquireAsync(CancellationToken cancellationToken)
    {
        await _turn.WaitAsync(cancellationToken).ConfigureAwait(false);
        return new Turn(_turn);
    }

    public void Dispose() => _turn.Dispose();

    private sealed class Turn(SemaphoreSlim turn) : IDisposable
    {
        private int _released;

        public void Dispose()
        {
            if (Interlocked.Exchange(ref _released, 1) == 0)
            {
                turn.Release();
            }
        }
    }
}
