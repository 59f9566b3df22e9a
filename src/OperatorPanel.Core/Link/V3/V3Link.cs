using System.Collections.Concurrent;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Protocol.V3;
using OperatorPanel.Core.Transport;
using Serilog;

namespace OperatorPanel.Core.Link.V3;

/// <summary>
/// Request/reply over one bus in protocol v3 (binary frames, Core/Protocol/V3), for the same Bus and polling loop as
/// <see cref="PlcLink"/> (docs/v3-panel-side.md; work in progress, not the default link). Two faces: the
/// <see cref="IPlcLink"/> one (V3Link.Translate.cs) carries the commands both protocols share (IDENTIFY, a READ of one
/// range, WRITE, WRITE BIT, STOP) so the writer, STOP and the settling of cut-short writes work unchanged; the native one,
/// <see cref="ExchangeV3Async"/>, carries the list commands the v3 readers (Polling/Readers/V3*) send. Every reply is
/// matched by REQCHECK; a request is retried only when it does not act on the process and no handler state moved on
/// with a lost reply (<see cref="RetriesFor"/>). Three files by concern: the exchange (here), the translation, the probe
/// that tells an older handler from a silent station (.OlderHandler).
/// </summary>
public sealed partial class V3Link : IPlcLink, IAsyncDisposable
{
    private readonly ITransport _transport;
    private readonly LinkOptions _options;
    private readonly TimeProvider _time;
    private readonly ILogger _log;
    private readonly Reader _reader = new();
    private readonly byte[] _buffer = new byte[512];
    private readonly ConcurrentDictionary<Station, StationStatistics> _statistics = new();
    private readonly ConcurrentDictionary<Station, Identity> _identities = new();
    private readonly ConcurrentDictionary<Station, bool> _spokeV3 = new();

    // Stations asked once whether an older handler answers, after a READ got no answer (opanel read and write start
    // with a READ, not an IDENTIFY): once per link, so an offline station costs the probe's time only once.
    private readonly ConcurrentDictionary<Station, bool> _probedAfterRead = new();
    private readonly PortReopener _port;
    private long? _lastExchangeEnd;
    private readonly Lock _endTimeoutLock = new();
    private int _longestEndTimeoutMs;
    private int _longestScanMs;
    private byte _sequence;

    public V3Link(ITransport transport, LinkOptions options, TimeProvider? time = null, ILogger? log = null)
    {
        ArgumentNullException.ThrowIfNull(transport);
        ArgumentNullException.ThrowIfNull(options);
        (_transport, _options, _time) = (transport, options, time ?? TimeProvider.System);
        _log = (log ?? Serilog.Core.Logger.None).ForContext<V3Link>();
        _port = new PortReopener(transport, _time, _log);
    }

    /// <summary>How the link reopens its port after a failure (<see cref="PortReopener"/>, as <see cref="PlcLink"/>).</summary>
    public ReconnectOptions Reconnect
    {
        get => _port.Options;
        init => _port.Options = value;
    }

    /// <summary>The port problem being worked around ("... - reconnecting"); null while connected.</summary>
    public string? Outage => _port.Outage;

    public string PortName => _transport.Name;

    public LinkStatistics StatisticsFor(Station station) =>
        _statistics.TryGetValue(station, out var statistics) ? statistics.Snapshot() : LinkStatistics.Empty;

    /// <summary>What the station's last v3 IDENTIFY reported (its handler's shape: list or not, MAX_DATA); null before one.</summary>
    public Identity? IdentityOf(Station station) => _identities.GetValueOrDefault(station);

    /// <summary>
    /// Identical-frame retries: none for WRITE, WRITE BITS and STOP (they act on the process: a lost reply is settled by
    /// reading back) and none for READ LIST (the handler's copy moved on with the lost reply: the next read is READ LIST
    /// FULL). IDENTIFY, READ, DEFINE LIST (it defines the same list again) and READ LIST FULL are repeated safely.
    /// </summary>
    public int RetriesFor(Command command) => command switch
    {
        Command.Write or Command.WriteBits or Command.Stop or Command.ReadList => 0,
        _ => _options.Retries,
    };

    public async ValueTask DisposeAsync() => await _transport.DisposeAsync().ConfigureAwait(false);

    /// <summary>
    /// Sends <paramref name="request"/> under the link's next SEQ and returns the reply whose REQCHECK is the frame's,
    /// or the failure after the retries <see cref="RetriesFor"/> allows. Throws only when cancelled.
    /// </summary>
    public async Task<V3Exchange> ExchangeV3Async(Request request, CancellationToken cancellationToken)
    {
        ArgumentNullException.ThrowIfNull(request);
        _sequence = (byte)((_sequence + 1) % Limits.SequenceCount);
        request = request with { Sequence = _sequence };
        var frame = Codec.Encode(request);
        var statistics = _statistics.GetOrAdd(request.Station, _ => new StationStatistics());
        var timeout = ReplyTimeoutFor(request.Command, frame.Length);
        var retries = RetriesFor(request.Command);
        var corruptedCopy = false;
        PlcCommunicationException? last = null;
        for (var attempt = 0; attempt <= retries; attempt++)
        {
            if (attempt > 0)
            {
                statistics.Retry();
                _log.Debug("{Station}: retry {Attempt} of v3 {Command} after {Reason}", request.Station, attempt, request.Command, last!.Message);
            }

            Attempt outcome;
            var sent = false;
            try
            {
                await _port.EnsureOpenAsync(cancellationToken).ConfigureAwait(false);
                await WaitForGapAsync(cancellationToken).ConfigureAwait(false);
                _transport.DiscardInput();
                _reader.Reset();
                var started = _time.GetTimestamp();
                sent = true;
                await _transport.WriteAsync(frame, cancellationToken).ConfigureAwait(false);
                outcome = await ReceiveAsync(request, frame, started, timeout, cancellationToken).ConfigureAwait(false);
                _lastExchangeEnd = _time.GetTimestamp();
            }
            catch (PlcCommunicationException port)
            {
                if (sent)
                {
                    statistics.Request();
                }

                var why = port.Station is null ? _port.PortFailureMessage(port) : port.Message;
                var failure = new PlcCommunicationException(port.Kind, request.Station, $"{request.Station}: {why}", port);
                return V3Exchange.Failed(failure, sent);
            }

            statistics.Request();
            if (outcome.Reply is { } reply)
            {
                statistics.Reply(outcome.Elapsed);
                _log.Verbose("{Station}: v3 {Command} SEQ {Sequence} -> {Status}, {PayloadBytes} payload bytes, {Milliseconds:0.0} ms",
                    request.Station, request.Command, request.Sequence, reply.Status, reply.Payload.Length, outcome.Elapsed.TotalMilliseconds);
                if (reply.Status.IsError())
                {
                    statistics.NegativeReply();
                    _log.Debug("{Station}: v3 {Command} refused: {Status}", request.Station, request.Command, reply.Status);
                }

                _spokeV3[request.Station] = true;
                return V3Exchange.Answered(reply);
            }

            last = outcome.Failure!;
            corruptedCopy |= outcome.CorruptedCopy;
            if (last.Kind == PlcErrorKind.Timeout)
            {
                statistics.Timeout();
            }
            else
            {
                statistics.Corrupt();
            }
        }

        var kind = last!.Kind == PlcErrorKind.Timeout && !corruptedCopy ? PlcErrorKind.NoAnswer : PlcErrorKind.FrameCorrupt;
        var attempts = retries == 0 ? "sent once, never repeated" : $"after {retries + 1} attempts";
        var message = $"{request.Station} on {_transport.Name}: no valid reply to v3 {request.Command} {attempts} ({last.Message})";
        if (kind == PlcErrorKind.NoAnswer && !_spokeV3.ContainsKey(request.Station)
            && (request.Command == Command.Identify || (request.Command == Command.Read && _probedAfterRead.TryAdd(request.Station, true)))
            && await OlderHandlerAsync(request.Station, cancellationToken).ConfigureAwait(false) is { } found)
        {
            return V3Exchange.Failed(new PlcCommunicationException(PlcErrorKind.HandlerOutdated, request.Station, HandlerBeforeV3.Message(request.Station, found)), sent: true);
        }

        _log.Debug("{Message}", message);
        return V3Exchange.Failed(new PlcCommunicationException(kind, request.Station, message), sent: true, corruptedCopy);
    }

    /// <summary>
    /// Frames that are not a reply (our own echo, another station's request: STATUS without bit 7) are skipped, and so
    /// is a reply to another frame (a late one, or one to a corrupted copy of ours: remembered); a frame that fails its
    /// check ends the attempt.
    /// </summary>
    private async Task<Attempt> ReceiveAsync(Request request, byte[] frame, long started, TimeSpan timeout, CancellationToken cancellationToken)
    {
        var corruptedCopy = false;
        while (true)
        {
            var remaining = timeout - _time.GetElapsedTime(started);
            if (remaining <= TimeSpan.Zero)
            {
                var why = corruptedCopy ? "only a reply to another frame than ours came (the PLC may have acted on a corrupted copy)" : $"no reply within {timeout.TotalMilliseconds:0} ms";
                return Attempt.Failed(corruptedCopy ? PlcErrorKind.FrameCorrupt : PlcErrorKind.Timeout, request, why) with { CorruptedCopy = corruptedCopy };
            }

            var count = await _transport.ReadAsync(_buffer, remaining, cancellationToken).ConfigureAwait(false);
            _reader.Append(_buffer.AsSpan(0, count));
            while (_reader.TryTake(out var received))
            {
                if (Codec.TryDecodeReplyTo(received, frame, out var reply, out var error))
                {
                    return new Attempt(reply, null, _time.GetElapsedTime(started));
                }

                switch (error)
                {
                    case DecodeError.BadHeader:
                        _log.Debug("{Station}: skipped a frame that is not a reply", request.Station);
                        break;
                    case DecodeError.RequestCheckMismatch:
                        // A refusal changed nothing; any other reply to a frame that is not ours may be the PLC acting on a corrupted copy.
                        corruptedCopy |= Codec.TryDecodeReply(received, out var other, out _) && !other.Status.IsError();
                        _log.Warning("{Station}: v3 {Command}: a reply whose REQCHECK is not the request's was skipped", request.Station, request.Command);
                        break;
                    default:
                        return Attempt.Failed(PlcErrorKind.FrameCorrupt, request, $"reply unusable: {error}") with { CorruptedCopy = corruptedCopy };
                }
            }
        }
    }

    /// <summary>
    /// The reply-time budget: request and longest reply on the wire, the end time-out the receive waits (the longer of
    /// <see cref="LinkOptions.ReplyDelay"/> and the longest END_TIMEOUT_MS an IDENTIFY on this link reported), one scan
    /// before the handler starts, the handler's scans for the command (<see cref="V3HandlerScans"/>), what the medium
    /// adds, and the margin. A scan is allowed the options' figures or, when an IDENTIFY reported a longer longest scan
    /// (SMW26), that scan and a quarter more: a CPU scanning in 100 ms takes about a second for a READ.
    /// </summary>
    internal TimeSpan ReplyTimeoutFor(Command command, int requestBytes)
    {
        var replyBytes = Limits.MaxFrameBytes;
        var endTimeout = TimeSpan.FromMilliseconds(Volatile.Read(ref _longestEndTimeoutMs));
        var reported = TimeSpan.FromMilliseconds(Volatile.Read(ref _longestScanMs) * 1.25);
        var perScan = reported > _options.HandlerScanAllowance ? reported : _options.HandlerScanAllowance;
        var first = reported > _options.ScanAllowance ? reported : _options.ScanAllowance;
        return (_options.Serial.CharacterTime * (requestBytes + replyBytes)) + (endTimeout > _options.ReplyDelay ? endTimeout : _options.ReplyDelay)
            + first + (perScan * V3HandlerScans.For(command))
            + _options.Medium.ExtraFor(_options.Serial, requestBytes, replyBytes) + _options.Margin;
    }

    /// <summary>
    /// The quiet time before a request: the options' gap, raised to END_TIMEOUT_MS + one character for the longest
    /// END_TIMEOUT_MS a station on this link reported (a station generated with a longer one than the line's default
    /// would otherwise merge our request into the message its RCV is still receiving). No gap when the options have none (tests).
    /// </summary>
    private async Task WaitForGapAsync(CancellationToken cancellationToken)
    {
        if (_lastExchangeEnd is not { } end || _options.InterFrameGap <= TimeSpan.Zero)
        {
            return;
        }

        var learned = V3LinkOptions.MinimumGap(_options.Serial, Volatile.Read(ref _longestEndTimeoutMs));
        var gap = learned > _options.InterFrameGap ? learned : _options.InterFrameGap;
        var wait = gap - _time.GetElapsedTime(end);
        if (wait > TimeSpan.Zero)
        {
            await Task.Delay(TimeSpan.FromMilliseconds(Math.Ceiling(wait.TotalMilliseconds)), _time, cancellationToken).ConfigureAwait(false);
        }
    }

    private sealed record Attempt(Reply? Reply, PlcCommunicationException? Failure, TimeSpan Elapsed)
    {
        public bool CorruptedCopy { get; init; }

        public static Attempt Failed(PlcErrorKind kind, Request request, string message) =>
            new(null, new PlcCommunicationException(kind, request.Station, message), TimeSpan.Zero);
    }
}
