using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Tests.Polling;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Core.Tests.Writes;

/// <summary>
/// A link in front of a <see cref="FakePlcLink"/> that loses the next write's reply: after the PLC applied it, or with
/// the request itself lost on the way. Later requests (the read-back) pass, or fail with <see cref="ReadBackFailure"/>.
/// </summary>
internal sealed class ReplyLosingLink(FakePlcLink plc) : IPlcLink
{
    /// <summary>What happens to the next WRITE or WRITE BIT: null passes it through.</summary>
    public WriteFate? NextWrite { get; set; }

    /// <summary>Thrown for every request after a lost write reply; null lets the read-back through.</summary>
    public PlcCommunicationException? ReadBackFailure { get; set; }

    /// <summary>Called after the lost write, before the read-back: the PLC program acting meanwhile.</summary>
    public Action? BetweenWriteAndReadBack { get; set; }

    public List<PlcRequest> Sent { get; } = [];

    public async Task<PlcResponse> ExchangeAsync(PlcRequest request, CancellationToken cancellationToken)
    {
        Sent.Add(request);
        if (ReadBackFailure is { } failure)
        {
            throw failure;
        }

        return await plc.ExchangeAsync(request, cancellationToken);
    }

    public async Task<OnceReply> ExchangeOnceAsync(PlcRequest request, CancellationToken cancellationToken)
    {
        var fate = NextWrite;
        NextWrite = null;
        switch (fate)
        {
            case null:
                Sent.Add(request);
                return new OnceReply.Answered(await plc.ExchangeAsync(request, cancellationToken));
            case WriteFate.NeverSent:
                return new OnceReply.NotSent(new PlcCommunicationException(PlcErrorKind.PortUnavailable, request.Station, "COM9 is gone"));
            case WriteFate.AppliedReplyLost or WriteFate.AppliedToCorruptedCopy:
                Sent.Add(request);
                await plc.ExchangeAsync(request, cancellationToken);
                BetweenWriteAndReadBack?.Invoke();
                return new OnceReply.ReplyLost("no reply within 120 ms", fate == WriteFate.AppliedToCorruptedCopy);
            case WriteFate.RequestLost:
                Sent.Add(request);
                BetweenWriteAndReadBack?.Invoke();
                return new OnceReply.ReplyLost("no reply within 120 ms", CorruptedCopy: false);
            default:
                throw new ArgumentOutOfRangeException(nameof(request), fate, null);
        }
    }

    public LinkStatistics StatisticsFor(Station station) => LinkStatistics.Empty;

    public bool IsOnline(Station station) => true;
}
