using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Core.Ppi;

/// <summary>The FDL handshake of one job: request and acknowledge, then polls until the answer (docs/ppi.md section 4).</summary>
public sealed partial class PpiMaster
{
    /// <summary>
    /// Sends <paramref name="job"/> to <paramref name="station"/> and returns the PDU it answers with, unchecked beyond
    /// the FDL layer. A request without acknowledge is sent again (the same frame: FCV = 0, so the CPU takes it as new);
    /// a poll without a sound answer is repeated with the same frame count bit, which asks the CPU to repeat its last
    /// answer (PROFIBUS spec part 4 p. 131). For a job that acts on the process use the write path, which sends the job
    /// once.
    /// </summary>
    public Task<byte[]> ExchangeAsync(Station station, byte[] job, CancellationToken cancellationToken) =>
        ExchangeAsync(station, job, JobSending.RepeatUnacknowledged, cancellationToken);

    /// <summary>
    /// The exchange, with the job sent once (<see cref="JobSending.Once"/>) or repeated while unacknowledged. Only the
    /// job's SD2 frame differs: a poll carries no job, so repeating it (same FCB: the CPU repeats its answer and does
    /// nothing again) is safe for every job.
    /// </summary>
    private async Task<byte[]> ExchangeAsync(Station station, byte[] job, JobSending sending, CancellationToken cancellationToken)
    {
        ArgumentNullException.ThrowIfNull(job);
        var address = (byte)station.Address;
        var request = PpiFrameCodec.Encode(PpiFrame.Variable(address, Options.MasterAddress, PpiFunctionCode.FirstRequest, job));
        var jobRetries = sending == JobSending.Once ? 0 : Options.Retries;
        var answer = await SendAsync(station, request, acknowledgeOnly: true, jobRetries, cancellationToken).ConfigureAwait(false);
        var frameCount = false;
        var polled = false;
        var pollsUntil = _time.GetTimestamp() + Ticks(Options.AnswerTimeout);
        while (answer is null)
        {
            if (_time.GetTimestamp() > pollsUntil)
            {
                throw new PlcCommunicationException(PlcErrorKind.Timeout, station,
                    $"{station} acknowledged the job but had no answer within {Options.AnswerTimeout.TotalMilliseconds:0} ms of polling: is its scan that long?");
            }

            if (Options.PollPause > TimeSpan.Zero && polled)
            {
                await Task.Delay(Options.PollPause, _time, cancellationToken).ConfigureAwait(false);
            }

            var poll = PpiFrameCodec.Encode(PpiFrame.Fixed(address, Options.MasterAddress, PpiFunctionCode.Poll(frameCount)));
            answer = await SendAsync(station, poll, acknowledgeOnly: false, Options.Retries, cancellationToken).ConfigureAwait(false);
            frameCount = !frameCount;
            polled = true;
            EmptyPolls += answer is null ? 1 : 0;
        }

        Exchanges++;
        return [.. answer.Value];
    }

    /// <summary>
    /// Sends <paramref name="frame"/> (again, up to <paramref name="retries"/> times) until the station answers soundly:
    /// null for 16#E5, or the data of its SD2 answer to us. With <paramref name="acknowledgeOnly"/> 16#E5 is what is
    /// expected, but an immediate data answer is taken too.
    /// </summary>
    private async Task<ImmutableArray<byte>?> SendAsync(Station station, byte[] frame, bool acknowledgeOnly, int retries, CancellationToken cancellationToken)
    {
        var what = acknowledgeOnly ? "the job" : "a poll";
        string? garbled = null;
        for (var attempt = 0; attempt <= retries; attempt++)
        {
            Repeats += attempt > 0 ? 1 : 0;
            _transport.DiscardInput();
            _reader.Reset();
            await _transport.WriteAsync(frame, cancellationToken).ConfigureAwait(false);
            var wait = Options.Characters(frame.Length) + Options.ReplyTimeout;
            var (outcome, data, problem) = await ReceiveAsync(station, wait, cancellationToken).ConfigureAwait(false);
            switch (outcome)
            {
                case Outcome.Acknowledged:
                    return null;
                case Outcome.Answered:
                    return data;
                case Outcome.Garbled:
                    garbled = problem;
                    _log.Debug("{Station}: garbled answer to {What} ({Problem}), attempt {Attempt}", station, what, problem, attempt + 1);
                    break;
                default:
                    _log.Debug("{Station}: no answer to {What}, attempt {Attempt}", station, what, attempt + 1);
                    break;
            }
        }

        throw garbled is null
            ? new PlcCommunicationException(PlcErrorKind.NoAnswer, station,
                $"{station} did not answer {what} ({(retries == 0 ? "sent once" : $"{retries + 1} tries")}): is a CPU at PPI address {station.Address} on the bus at this baud rate, 8 data bits, even parity?")
            : new PlcCommunicationException(PlcErrorKind.FrameCorrupt, station, $"{station}: garbled answer to {what}: {garbled}");
    }

    /// <summary>Reads until the station's answer, a broken telegram, or <paramref name="wait"/> without one.</summary>
    private async Task<(Outcome Outcome, ImmutableArray<byte>? Data, string? Problem)> ReceiveAsync(Station station, TimeSpan wait, CancellationToken cancellationToken)
    {
        var deadline = _time.GetTimestamp() + Ticks(wait);
        while (true)
        {
            while (_reader.TryTake(out var result))
            {
                if (Classify(station, result) is { } outcome)
                {
                    return outcome;
                }
            }

            var now = _time.GetTimestamp();
            if (now >= deadline)
            {
                return _reader.PendingChars > 0 ? (Outcome.Garbled, null, "the answer stopped short") : (Outcome.Silent, null, null);
            }

            var count = await _transport.ReadAsync(_buffer, _time.GetElapsedTime(now, deadline), cancellationToken).ConfigureAwait(false);
            _reader.Append(_buffer.AsSpan(0, count));
            if (count > 0 && _reader.MissingChars > 0)
            {
                // A telegram is arriving: give it the time its missing characters take (a USB adapter may hand them over late).
                deadline = Math.Max(deadline, _time.GetTimestamp() + Ticks(Options.Characters(_reader.MissingChars) + Options.ReplyTimeout));
            }
        }
    }

    /// <summary>What one telegram means for the exchange; null for our own echo, which some RS-485 adapters return.</summary>
    private (Outcome, ImmutableArray<byte>?, string?)? Classify(Station station, PpiReadResult result)
    {
        if (result.Frame is not { } frame)
        {
            return (Outcome.Garbled, null, $"broken telegram ({result.Error})");
        }

        var master = Options.MasterAddress;
        if (frame.Kind == PpiFrameKind.ShortAcknowledge)
        {
            return (Outcome.Acknowledged, null, null);
        }

        if (frame.Kind != PpiFrameKind.Token && frame.Source == master)
        {
            return null;
        }

        if (frame.Kind != PpiFrameKind.Token && frame.Source == station.Address && frame.Destination == master)
        {
            return frame.Kind == PpiFrameKind.Variable && PpiFunctionCode.IsDataResponse(frame.FunctionCode)
                ? (Outcome.Answered, frame.Data, null)
                : (Outcome.Garbled, null, $"an answer with function code 16#{frame.FunctionCode:X2} instead of data");
        }

        throw new PlcCommunicationException(PlcErrorKind.AnotherMaster, station,
            $"another master is on the bus (seen: {frame}); the panel is the only master it supports and stopped instead of competing for the bus");
    }

    private long Ticks(TimeSpan span) => (long)(span.TotalSeconds * _time.TimestampFrequency);

    private enum JobSending
    {
        /// <summary>Reads and set-up: a job without acknowledge is sent again (FCV = 0: the CPU takes it as new, and a read does nothing twice).</summary>
        RepeatUnacknowledged,

        /// <summary>Writes: a job without acknowledge may still have reached the CPU, and sent again it would be done again.</summary>
        Once,
    }

    private enum Outcome
    {
        Silent,
        Acknowledged,
        Answered,
        Garbled,
    }
}
