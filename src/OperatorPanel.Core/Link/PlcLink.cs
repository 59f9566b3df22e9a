using System.Collections.Concurrent;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Transport;
using Serilog;
using Serilog.Events;

namespace OperatorPanel.Core.Link;

/// <summary>
/// Request/response over one bus: a reply-time budget per request, retries of the identical frame, per-station
/// statistics. The link stamps every request with its own next sequence number (whatever the caller put there), so
/// replies for an older request, and the echo of our own request that some RS-485 adapters return, are skipped rather
/// than taken for the answer. One request at a time: its bus (Line/Bus) is its one caller, through the bus's queue.
/// Whether a station is online is not the link's business: the bus's station states (Polling/StationTracker) keep it.
/// Four files by concern, one type because all four share the transport, the frame reader, the sequence number and the
/// gap timing of one wire: the exchange and its retries (here), receiving one attempt's reply (.Receive), getting a
/// vanished port back (.Reconnect), the v1 IDENTIFY probe (.V1Probe).
/// </summary>
public sealed partial class PlcLink : IPlcLink, IAsyncDisposable
{
    private readonly ITransport _transport;
    private readonly LinkOptions _options;
    private readonly TimeProvider _time;
    private readonly ILogger _log;
    private readonly FrameReader _reader = new();
    private readonly byte[] _buffer = new byte[512];
    private readonly ConcurrentDictionary<Station, StationStatistics> _statistics = new();

    /// <summary>Stations that gave a valid v2 reply on this link: their silence is never a v1 handler's.</summary>
    private readonly ConcurrentDictionary<Station, bool> _spokeV2 = new();
    private long? _lastExchangeEnd;
    private byte _sequence;

    /// <summary>Whether the exchange under way handed its frame to the port (so the PLC may have got it).</summary>
    private bool _frameSent;

    public PlcLink(ITransport transport, LinkOptions options, TimeProvider? time = null, ILogger? log = null)
    {
        ArgumentNullException.ThrowIfNull(transport);
        ArgumentNullException.ThrowIfNull(options);
        _transport = transport;
        _options = options;
        _time = time ?? TimeProvider.System;
        _log = (log ?? Serilog.Core.Logger.None).ForContext<PlcLink>();
        _port = new PortReopener(transport, _time, _log);
    }

    public string PortName => _transport.Name;

    public LinkStatistics StatisticsFor(Station station) =>
        _statistics.TryGetValue(station, out var statistics) ? statistics.Snapshot() : LinkStatistics.Empty;

    /// <summary>
    /// True for the commands that act on the process: WRITE, WRITE BIT, STOP. They are sent once: after a lost reply the
    /// PLC may have acted, and a repeat could act twice (a bit the PLC program resets at once, a value it changed meanwhile).
    /// </summary>
    public static bool ActsOnProcess(CommandCode command) => command switch
    {
        CommandCode.Write or CommandCode.WriteBit or CommandCode.Stop => true,
        CommandCode.Identify or CommandCode.Read or CommandCode.DefineList or CommandCode.ReadList or CommandCode.ReadChanges
            or CommandCode.ReadChangesOfLists => false,
    };

    /// <summary>
    /// Identical-frame retries a request gets: none for one that acts on the process, and none for READ CHANGES without
    /// FULL or READ CHANGES OF LISTS, whose handler copies moved on with the lost reply (docs/protocol-v2.md, PC rule: the
    /// next read of each list must be FULL).
    /// </summary>
    private int RetriesFor(PlcRequest request) =>
        ActsOnProcess(request.Command) || request is ReadChangesRequest { Full: false } or ReadChangesOfListsRequest ? 0 : _options.Retries;

    public async ValueTask DisposeAsync() => await _transport.DisposeAsync().ConfigureAwait(false);

    public async Task<LinkReply> ExchangeAsync(PlcRequest request, CancellationToken cancellationToken)
    {
        ArgumentNullException.ThrowIfNull(request);

        // Retries resend the same frame and so the same number.
        request = request with { Sequence = unchecked(++_sequence) };
        var statistics = _statistics.GetOrAdd(request.Station, _ => new StationStatistics());
        var frame = RequestCodec.Encode(request);
        var timeout = _options.ReplyTimeoutFor(request, frame.Length);
        var retries = RetriesFor(request);
        _frameSent = false;
        PlcCommunicationException? lastFailure = null;
        var refusalRetried = false;
        var corruptedCopy = false;

        for (var attempt = 0; attempt <= retries; attempt++)
        {
            if (attempt > 0)
            {
                statistics.Retry();
                _log.Debug("{Station}: retry {Attempt} of {Command} after {Reason}", request.Station, attempt, request.Command, lastFailure!.Message);
            }

            AttemptOutcome outcome;
            try
            {
                outcome = await AttemptAsync(request, frame, timeout, cancellationToken).ConfigureAwait(false);
            }
            catch (PlcCommunicationException portFailure)
            {
                if (_frameSent)
                {
                    statistics.Request();
                }

                return new LinkReply.Failed(portFailure, _frameSent);
            }

            // Counted once the attempt has ended, so a snapshot taken while a frame is in flight does not show a
            // request without its reply or timeout.
            statistics.Request();
            if (_log.IsEnabled(LogEventLevel.Verbose))
            {
                // Guarded: the five arguments would be boxed into an array on every exchange even with Verbose off.
                _log.Verbose(
                    "{Station}: {Command} SEQ {Sequence}, {Characters} characters: {Outcome}",
                    request.Station,
                    request.Command,
                    request.Sequence,
                    frame.Length,
                    outcome.Response?.GetType().Name ?? outcome.Failure?.Message);
            }

            if (outcome.CorruptedRefusal is { } refusal)
            {
                // The PLC refused a corrupted copy, so it did nothing: one more attempt is safe, even for a write.
                statistics.CorruptedRefusal();
                if (!refusalRetried)
                {
                    refusalRetried = true;
                    retries = Math.Max(retries, attempt + 1);
                    lastFailure = outcome.Failure;
                    continue;
                }

                _log.Warning("{Station}: {Command} refused again after a corrupted refusal: taken as real", request.Station, request.Command);
                outcome = AttemptOutcome.Answered(refusal, outcome.Elapsed);
            }

            if (outcome.Response is { } response)
            {
                statistics.Reply(outcome.Elapsed);
                if (response is ErrorResponse negative)
                {
                    statistics.NegativeReply();
                    // Debug only: the caller says what the refusal means (a READ's station status, a write's outcome),
                    // and some are expected (the engine's clearing DEFINE LIST).
                    _log.Debug("{Station}: {Command} refused: {Error}", request.Station, request.Command, negative.Error);
                }

                _spokeV2[request.Station] = true;
                return new LinkReply.Answered(response);
            }

            lastFailure = outcome.Failure!;
            corruptedCopy |= outcome.CorruptedCopy;
            if (lastFailure.Kind == PlcErrorKind.Timeout)
            {
                statistics.Timeout();
            }
            else
            {
                statistics.Corrupt();
            }
        }

        var kind = lastFailure!.Kind == PlcErrorKind.Timeout ? PlcErrorKind.NoAnswer : PlcErrorKind.FrameCorrupt;
        var attempts = ActsOnProcess(request.Command) ? "sent once, never repeated" : $"after {retries + 1} attempts";
        var message = $"{request.Station} on {_transport.Name}: no valid reply to {request.Command} {attempts} ({lastFailure.Message})";
        if (kind == PlcErrorKind.NoAnswer && request is IdentifyRequest identify && !_spokeV2.ContainsKey(identify.Station)
            && await AnswersV1ProbeAsync(identify, statistics, cancellationToken).ConfigureAwait(false))
        {
            return new LinkReply.Failed(new PlcCommunicationException(PlcErrorKind.HandlerOutdated, request.Station, HandlerV1.Message(request.Station)), Sent: true);
        }

        // Debug: the bus's station states log a station falling silent, once (Polling/StationTracker).
        _log.Debug("{Message}", message);
        return new LinkReply.Failed(new PlcCommunicationException(kind, request.Station, message), Sent: true, corruptedCopy);
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
            _frameSent = true;
            await _transport.WriteAsync(frame, cancellationToken).ConfigureAwait(false);
            var outcome = await ReceiveAsync(request, started, timeout, cancellationToken).ConfigureAwait(false);
            _lastExchangeEnd = _time.GetTimestamp();
            return outcome;
        }
        catch (PlcCommunicationException ex) when (ex.Station is null)
        {
            throw new PlcCommunicationException(ex.Kind, request.Station, $"{request.Station}: {PortFailureMessage(ex)}", ex);
        }
    }

    private async Task WaitForInterFrameGapAsync(CancellationToken cancellationToken)
    {
        if (_lastExchangeEnd is not { } end || _options.InterFrameGap <= TimeSpan.Zero)
        {
            return;
        }

        // Task.Delay counts whole milliseconds and truncates: round up, or 24.99 ms would wait 24.
        var wait = _options.InterFrameGap - _time.GetElapsedTime(end);
        if (wait > TimeSpan.Zero)
        {
            await Task.Delay(TimeSpan.FromMilliseconds(Math.Ceiling(wait.TotalMilliseconds)), _time, cancellationToken).ConfigureAwait(false);
        }
    }
}
