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

    /// <summary>The failure of every request after a lost write reply; null lets the read-back through.</summary>
    public PlcCommunicationException? ReadBackFailure { get; set; }

    /// <summary>Called after the lost write, before the read-back: the PLC program acting meanwhile.</summary>
    public Action? BetweenWriteAndReadBack { get; set; }

    public List<PlcRequest> Sent { get; } = [];

    public async Task<LinkReply> ExchangeAsync(PlcRequest request, CancellationToken cancellationToken)
    {
        if (PlcLink.ActsOnProcess(request.Command))
        {
            return await WriteAsync(request, cancellationToken);
        }

        Sent.Add(request);
        if (ReadBackFailure is { } failure)
        {
            return new LinkReply.Failed(failure, Sent: true);
        }

        return await plc.ExchangeAsync(request, cancellationToken);
    }

    public LinkStatistics StatisticsFor(Station station) => LinkStatistics.Empty;

    private async Task<LinkReply> WriteAsync(PlcRequest request, CancellationToken cancellationToken)
    {
        var fate = NextWrite;
        NextWrite = null;
        switch (fate)
        {
            case null:
                Sent.Add(request);
                return await plc.ExchangeAsync(request, cancellationToken);
            case WriteFate.NeverSent:
                return new LinkReply.Failed(new PlcCommunicationException(PlcErrorKind.PortUnavailable, request.Station, "COM9 is gone"), Sent: false);
            case WriteFate.AppliedReplyLost or WriteFate.AppliedToCorruptedCopy:
                Sent.Add(request);
                await plc.ExchangeAsync(request, cancellationToken);
                BetweenWriteAndReadBack?.Invoke();
                return new LinkReply.Failed(Lost(request), Sent: true, fate == WriteFate.AppliedToCorruptedCopy);
            case WriteFate.RequestLost:
                Sent.Add(request);
                BetweenWriteAndReadBack?.Invoke();
                return new LinkReply.Failed(Lost(request), Sent: true);
            default:
                throw new ArgumentOutOfRangeException(nameof(request), fate, null);
        }
    }

    private static PlcCommunicationException Lost(PlcRequest request) => new(PlcErrorKind.NoAnswer, request.Station, "no reply within 120 ms");
}
