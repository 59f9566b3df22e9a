using System.Globalization;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Core.Link;

/// <summary>
/// Receiving one attempt's reply: frames that are not the reply (our own echo, a late reply to an older request, another
/// station's) are skipped; a reply whose REQCHECK is not the check of the request sent answered a corrupted copy of it.
/// </summary>
public sealed partial class PlcLink
{
    private async Task<AttemptOutcome> ReceiveAsync(PlcRequest request, long started, TimeSpan timeout, CancellationToken cancellationToken)
    {
        var requestCheck = RequestCodec.Check(request);
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

                // Decoded once: the frame itself serves the REQCHECK mismatch below.
                if (FrameCodec.TryDecode(result.Frame.AsSpan(), out var frame, out var error)
                    && ResponseCodec.TryDecode(frame, request, requestCheck, out var response, out error))
                {
                    return AttemptOutcome.Answered(response, _time.GetElapsedTime(started));
                }

                if (error == FrameError.RequestCheckMismatch)
                {
                    return AnsweredACorruptedCopy(request, requestCheck, frame, _time.GetElapsedTime(started));
                }

                if (error is not (FrameError.NotAReply or FrameError.StationMismatch or FrameError.SequenceMismatch))
                {
                    return AttemptOutcome.Failed(PlcErrorKind.FrameCorrupt, request, $"reply unusable: {error}");
                }

                _log.Debug("{Station}: skipped a frame that is not the reply ({Error})", request.Station, error);
            }
        }
    }

    /// <summary>
    /// A valid reply to our STATION, SEQ and CMD whose REQCHECK is not our request's check: the PLC acted on a copy that
    /// noise changed and that still passed its check. An error reply is then no refusal of our request (retried once);
    /// any other reply is no answer to it, and for a write the PLC executed something else.
    /// </summary>
    private AttemptOutcome AnsweredACorruptedCopy(PlcRequest request, ushort requestCheck, FreeportFrame frame, TimeSpan elapsed)
    {
        var theirs = (ushort)((frame.Payload[1] << 8) | frame.Payload[2]);
        var status = frame.Payload[0];
        var message = string.Create(
            CultureInfo.InvariantCulture,
            $"the reply's REQCHECK 16#{theirs:X4} is not the request's 16#{requestCheck:X4}: the PLC acted on a corrupted copy");
        _log.Warning("{Station}: {Command}: {Problem} (status {Status})", request.Station, request.Command, message, status);
        var failure = AttemptOutcome.Failed(PlcErrorKind.FrameCorrupt, request, message);
        return status != 0 && Enum.IsDefined((ProtocolError)status)
            ? failure with { CorruptedRefusal = new ErrorResponse(request.Station, request.Sequence, request.Command, (ProtocolError)status) { RequestCheck = theirs }, Elapsed = elapsed }
            : failure with { CorruptedCopy = true };
    }

    private sealed record AttemptOutcome(PlcResponse? Response, PlcCommunicationException? Failure, TimeSpan Elapsed)
    {
        /// <summary>The reply answered a corrupted copy of the request and was no refusal: the PLC may have acted on it.</summary>
        public bool CorruptedCopy { get; init; }

        /// <summary>The reply refused a corrupted copy of the request: the PLC did nothing.</summary>
        public ErrorResponse? CorruptedRefusal { get; init; }

        public static AttemptOutcome Answered(PlcResponse response, TimeSpan elapsed) => new(response, null, elapsed);

        public static AttemptOutcome Failed(PlcErrorKind kind, PlcRequest request, string message) =>
            new(null, new PlcCommunicationException(kind, request.Station, message), TimeSpan.Zero);
    }
}
