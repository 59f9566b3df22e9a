using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Protocol.V1;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Core.Link;

/// <summary>
/// A station that answers no IDENTIFY v2 gets one v1 IDENTIFY (docs/protocol-v2.md, "Version 1 handlers"): a v1 handler
/// answers it, and the IDENTIFY then fails with <see cref="HandlerV1.Message"/> instead of "no answer". Not a station
/// that gave a valid v2 reply on this link before: its silence is a stopped or unplugged PLC (e.g. the IDENTIFY that
/// confirms a STOP), and the probe would only add one more reply time.
/// </summary>
public sealed partial class PlcLink
{
    /// <summary>
    /// In the same exchange, after IDENTIFY got no answer: sends the v1 probe under the next sequence number and waits one
    /// IDENTIFY reply time. True when a v1 handler answered. Counted as one more request (and its reply or timeout) once it
    /// has ended.
    /// </summary>
    private async Task<bool> AnswersV1ProbeAsync(IdentifyRequest identify, StationStatistics statistics, CancellationToken cancellationToken)
    {
        var sequence = unchecked(++_sequence);
        var probe = V1IdentifyProbe.Encode(identify.Station, sequence);
        var timeout = _options.ReplyTimeoutFor(identify);
        var started = _time.GetTimestamp();
        try
        {
            await WaitForInterFrameGapAsync(cancellationToken).ConfigureAwait(false);
            _transport.DiscardInput();
            _reader.Reset();
            started = _time.GetTimestamp();
            await _transport.WriteAsync(probe, cancellationToken).ConfigureAwait(false);
            while (_time.GetElapsedTime(started) is var elapsed && elapsed < timeout)
            {
                var count = await _transport.ReadAsync(_buffer, timeout - elapsed, cancellationToken).ConfigureAwait(false);
                _reader.Append(_buffer.AsSpan(0, count));
                while (_reader.TryTake(out var result))
                {
                    if (result.IsFrame && V1IdentifyProbe.TryDecodeReply(result.Frame.AsSpan(), identify.Station, sequence, out _))
                    {
                        statistics.Request();
                        statistics.Reply(_time.GetElapsedTime(started));
                        _log.Warning("{Message}", HandlerV1.Message(identify.Station));
                        return true;
                    }
                }
            }

            statistics.Request();
            statistics.Timeout();
            return false;
        }
        catch (PlcCommunicationException failure)
        {
            // The port failed under the probe: the IDENTIFY's own failure is the news, not this.
            _log.Debug("{Station}: v1 probe failed: {Reason}", identify.Station, failure.Message);
            return false;
        }
        finally
        {
            _lastExchangeEnd = _time.GetTimestamp();
        }
    }
}
