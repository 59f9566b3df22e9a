using OperatorPanel.Core.Link;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Core.Polling.Readers;

/// <summary>
/// 03 READ (docs/protocol-v2.md): one exchange per frame, its blocks listed in every request. Takes any frame, so it is the
/// last reader of every station: what no other reader takes (a frame without a list, a list whose DEFINE was refused,
/// every frame when read lists are off) is read here.
/// </summary>
internal sealed class PlainReader(PollingContext context) : IStationReader
{
    public async Task<IReadOnlyList<(int Frame, FrameRead Read)>> ReadAsync(IReadOnlyList<int> pending, CancellationToken cancellationToken)
    {
        ArgumentNullException.ThrowIfNull(pending);
        var index = pending[0];
        var frame = context.Plan.Frames[index];
        var reply = await context.Link.ExchangeAsync(new ReadRequest(frame.Station, frame.Items), cancellationToken).ConfigureAwait(false);
        var read = reply switch
        {
            LinkReply.Failed failed => context.Judge.Failed(frame.Station, failed.Failure),
            { Response: ReadResponse data } when data.Data.Length == frame.DataBytes => context.Judge.Data(frame.Station, data.Data),
            { Response: ErrorResponse refused } => context.Judge.Refused(frame, refused),
            _ => context.Judge.Unexpected(frame, reply.Response),
        };
        return [(index, read)];
    }
}
