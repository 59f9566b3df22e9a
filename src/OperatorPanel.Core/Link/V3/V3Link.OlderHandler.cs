using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Protocol.V1;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Core.Link.V3;

/// <summary>
/// A station silent to IDENTIFY v3 that never answered v3 on this link gets one v2 IDENTIFY and one v1 IDENTIFY: an
/// older handler ignores v3 frames (its RCV ends on '&gt;' and its check is over hex characters) but answers its own,
/// and the panel then says to regenerate the PLC code instead of "no answer". An older handler's RCV, opened by the
/// '&lt;' of our v3 frames, runs until a '&gt;': a lone '&gt;' ends it first (a v3 station ignores it: it waits for '&lt;'),
/// or the probe would only close the receive our v3 bytes opened.
/// </summary>
public sealed partial class V3Link
{
    private static readonly byte[] EndOfOlderFrame = [FrameCodec.EndChar];

    /// <summary>"a protocol v2 handler" or "a protocol v1 handler" when one answered its IDENTIFY; else null.</summary>
    private async Task<string?> OlderHandlerAsync(Station station, CancellationToken cancellationToken)
    {
        var v2 = RequestCodec.Encode(new IdentifyRequest(station, 1));
        if (await AnswersAsync(v2, chars => FrameCodec.TryDecode(chars, out var frame, out _) && frame.Station == station.Address && frame.IsReply, cancellationToken).ConfigureAwait(false))
        {
            return "an Operator Panel handler of protocol v2";
        }

        var v1 = V1IdentifyProbe.Encode(station, 1);
        return await AnswersAsync(v1, chars => V1IdentifyProbe.TryDecodeReply(chars, station, 1, out _), cancellationToken).ConfigureAwait(false)
            ? "an Operator Panel handler of protocol v1"
            : null;
    }

    /// <summary>Sends <paramref name="probe"/> and waits one reply time for a '&lt;' .. '&gt;' frame that <paramref name="fits"/>.</summary>
    private async Task<bool> AnswersAsync(byte[] probe, Func<byte[], bool> fits, CancellationToken cancellationToken)
    {
        var timeout = ReplyTimeoutFor(Protocol.V3.Command.Identify, probe.Length);
        var received = new List<byte>();
        try
        {
            await WaitForGapAsync(cancellationToken).ConfigureAwait(false);
            await _transport.WriteAsync(EndOfOlderFrame, cancellationToken).ConfigureAwait(false);
            _lastExchangeEnd = _time.GetTimestamp();
            await WaitForGapAsync(cancellationToken).ConfigureAwait(false);
            _transport.DiscardInput();
            var started = _time.GetTimestamp();
            await _transport.WriteAsync(probe, cancellationToken).ConfigureAwait(false);
            while (_time.GetElapsedTime(started) is var elapsed && elapsed < timeout)
            {
                var count = await _transport.ReadAsync(_buffer, timeout - elapsed, cancellationToken).ConfigureAwait(false);
                received.AddRange(_buffer.AsSpan(0, count));
                var start = received.LastIndexOf(FrameCodec.StartChar);
                var end = received.LastIndexOf(FrameCodec.EndChar);
                if (start >= 0 && end > start && fits([.. received.GetRange(start, end - start + 1)]))
                {
                    return true;
                }
            }

            return false;
        }
        catch (PlcCommunicationException failure)
        {
            _log.Debug("older-handler probe failed: {Reason}", failure.Message);
            return false;
        }
        finally
        {
            _lastExchangeEnd = _time.GetTimestamp();
        }
    }
}
