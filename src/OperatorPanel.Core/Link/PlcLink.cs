using System.Collections.Concurrent;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Transport;
using Serilog;

namespace OperatorPanel.Core.Link;

/// <summary>
/// Request/response over one bus: one request in flight (<see cref="BusArbiter"/>), a reply-time budget per request,
/// retries of the identical frame, per-station statistics and online state. The link stamps every request with its own
/// next sequence number (whatever the caller put there), so replies for an older request, and the echo of our own
/// request that some RS-485 adapters return, are skipped rather than taken for the answer.
/// </summary>
public sealed partial class PlcLink : IPlcLink, IAsyncDisposable
{
    private readonly ITransport _transport;
    private readonly LinkOptions _options;
    private readonly TimeProvider _time;
    private readonly ILogger _log;
    private readonly BusArbiter _arbiter = new();
    private readonly FrameReader _reader = new();
    private readonly byte[] _buffer = new byte[512];
    private readonly ConcurrentDictionary<Station, StationStatistics> _statistics = new();
    private readonly ConcurrentDictionary<Station, bool> _online = new();
    private long? _lastExchangeEnd;
    private byte _sequence;

    public PlcLink(ITransport transport, LinkOptions options, TimeProvider? time = null, ILogger? log = null)
    {
        ArgumentNullException.ThrowIfNull(transport);
        ArgumentNullException.ThrowIfNull(options);
        _transport = transport;
        _options = options;
        _time = time ?? TimeProvider.System;
        _log = (log ?? Serilog.Core.Logger.None).ForContext<PlcLink>();
    }

    public string PortName => _transport.Name;

    public LinkStatistics StatisticsFor(Station station) =>
        _statistics.TryGetValue(station, out var statistics) ? statistics.Snapshot() : LinkStatistics.Empty;

    public bool IsOnline(Station station) => _online.TryGetValue(station, out var online) && online;

    public async Task<PlcResponse> ExchangeAsync(PlcRequest request, CancellationToken cancellationToken)
    {
        ArgumentNullException.ThrowIfNull(request);
        using var turn = await _arbiter.AcquireAsync(cancellationToken).ConfigureAwait(false);

        // Under the turn, so numbers go out in order; retries resend the same frame and so the same number.
        request = request with { Sequence = unchecked(++_sequence) };
        var statistics = _statistics.GetOrAdd(request.Station, _ => new StationStatistics());
        var frame = RequestCodec.Encode(request);
        var timeout = _options.ReplyTimeoutFor(request, frame.Length);
        PlcCommunicationException? lastFailure = null;

        // A READ CHANGES without FULL is never repeated: the PLC's copy moved on with the reply we lost, so a repeat
        // would miss those changes (docs/protocol.md, READ CHANGES, PC rule 2). The polling engine asks FULL instead.
        var retries = request is ReadChangesRequest { Full: false } ? 0 : _options.Retries;
        for (var attempt = 0; attempt <= retries; attempt++)
        {
            if (attempt > 0)
            {
                statistics.Retry();
                _log.Debug("{Station}: retry {Attempt} of {Command} after {Reason}", request.Station, attempt, request.Command, lastFailure!.Message);
            }

            statistics.Request();
            var outcome = await AttemptAsync(request, frame, timeout, cancellationToken).ConfigureAwait(false);
            if (outcome.Response is { } response)
            {
                statistics.Reply(outcome.Elapsed);
                if (response is ErrorResponse negative)
                {
                    statistics.NegativeReply();
                    _log.Warning("{Station}: {Command} refused: {Error}", request.Station, request.Command, negative.Error);
                }

                _online[request.Station] = true;
                return response;
            }

            lastFailure = outcome.Failure!;
            if (lastFailure.Kind == PlcErrorKind.Timeout)
            {
                statistics.Timeout();
            }
            else
            {
                statistics.Corrupt();
            }
        }

        _online[request.Station] = false;
        var kind = lastFailure!.Kind == PlcErrorKind.Timeout ? PlcErrorKind.NoAnswer : PlcErrorKind.FrameCorrupt;
        var message = $"{request.Station} on {_transport.Name}: no valid reply to {request.Command} after {retries + 1} attempts ({lastFailure.Message})";
        _log.Warning("{Message}", message);
        throw new PlcCommunicationException(kind, request.Station, message);
    }

    public async ValueTask DisposeAsync()
    {
        _arbiter.Dispose();
        await _transport.DisposeAsync().ConfigureAwait(false);
    }

    private async Task<AttemptOutcome> AttemptAsync(PlcRequest request, byte[] frame, TimeSpan timeout, CancellationToken cancellationToken)
    {
        try
        {
            await EnsureOpenAsync(cancellationToken).ConfigureAwait(false);
            await WaitForInterFrameGapAsync(cancellationToken).ConfigureAwait(false);
            _transport.DiscardInput();
            _reader.Reset();
            var started = _time.GetTimestamp();
            await _transport.WriteAsync(frame, cancellationToken).ConfigureAwait(false);
            var outcome = await ReceiveAsync(request, started, timeout, cancellationToken).ConfigureAwait(false);
            _lastExchangeEnd = _time.GetTimestamp();
            return outcome;
        }
        catch (PlcCommunicationException ex) when (ex.Station is null)
        {
            _online[request.Station] = false;
            throw new PlcCommunicationException(ex.Kind, request.Station, $"{request.Station}: {PortFailureMessage(ex)}", ex);
        }
        catch (PlcCommunicationException)
        {
            _online[request.Station] = false;
            throw;
        }
    }

    private async Task<AttemptOutcome> ReceiveAsync(PlcRequest request, long started, TimeSpan timeout, CancellationToken cancellationToken)
    {
        while (true)
        {
            var remaining = timeout - _time.GetElapsedTime(started);
            if (remaining <= TimeSpan.Zero)
            {
                return AttemptOutcome.Failed(PlcErrorKind.Timeout, request, $"no reply within {timeout.TotalMilliseconds:0} ms");
            }

            var count = await _transport.ReadAsync(_buffer, remaining, cancellationToken).ConfigureAwait(false);
            if (count == 0)
            {
                continue;
            }

            _reader.Append(_buffer.AsSpan(0, count));
            while (_reader.TryTake(out var result))
            {
                if (!result.IsFrame)
                {
                    return AttemptOutcome.Failed(PlcErrorKind.FrameCorrupt, request, $"reply unusable: {result.Error}");
                }

                if (ResponseCodec.TryDecode(result.Frame.AsSpan(), request, out var response, out var error))
                {
                    return AttemptOutcome.Answered(response, _time.GetElapsedTime(started));
                }

                if (error is not (FrameError.NotAReply or FrameError.StationMismatch or FrameError.SequenceMismatch))
                {
                    return AttemptOutcome.Failed(PlcErrorKind.FrameCorrupt, request, $"reply unusable: {error}");
                }

                _log.Debug("{Station}: skipped a frame that is not the reply ({Error})", request.Station, error);
            }
        }
    }

    private async Task WaitForInterFrameGapAsync(CancellationToken cancellationToken)
    {
        if (_lastExchangeEnd is not { } end || _options.InterFrameGap <= TimeSpan.Zero)
        {
            return;
        }

        var wait = _options.InterFrameGap - _time.GetElapsedTime(end);
        if (wait > TimeSpan.Zero)
        {
            await Task.Delay(wait, _time, cancellationToken).ConfigureAwait(false);
        }
    }

    private sealed record AttemptOutcome(PlcResponse? Response, PlcCommunicationException? Failure, TimeSpan Elapsed)
    {
        public static AttemptOutcome Answered(PlcResponse response, TimeSpan elapsed) => new(response, null, elapsed);

        public static AttemptOutcome Failed(PlcErrorKind kind, PlcRequest request, string message) =>
            new(null, new PlcCommunicationException(kind, request.Station, message), TimeSpan.Zero);
    }
}
