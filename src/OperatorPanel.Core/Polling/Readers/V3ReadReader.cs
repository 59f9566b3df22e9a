using System.Collections.Immutable;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Core.Polling.Readers;

/// <summary>
/// v3 02 READ (docs/v3-panel-side.md): one range of 1 to MAX_DATA bytes per request, so a frame is read range by range,
/// each cut into pieces of at most <paramref name="maxData"/> bytes, through the link's <see cref="IPlcLink"/> face. The
/// last reader of every station of a v3 bus, and the only one of a compact handler (no list).
/// </summary>
internal sealed class V3ReadReader(PollingContext context, int maxData) : IStationReader
{
    public async Task<IReadOnlyList<(int Frame, FrameRead Read)>> ReadAsync(IReadOnlyList<int> pending, CancellationToken cancellationToken)
    {
        ArgumentNullException.ThrowIfNull(pending);
        var index = pending[0];
        var frame = context.Plan.Frames[index];
        var data = ImmutableArray.CreateBuilder<byte>(frame.DataBytes);
        foreach (var piece in frame.Items.SelectMany(Pieces))
        {
            var reply = await context.Link.ExchangeAsync(new ReadRequest(frame.Station, [piece]), cancellationToken).ConfigureAwait(false);
            switch (reply)
            {
                case LinkReply.Failed failed:
                    return [(index, context.Judge.Failed(frame.Station, failed.Failure))];
                case { Response: ReadResponse read } when read.Data.Length == piece.Length:
                    data.AddRange(read.Data);
                    break;
                case { Response: ErrorResponse refused }:
                    return [(index, context.Judge.Refused(frame, refused))];
                default:
                    return [(index, context.Judge.Unexpected(frame, reply.Response))];
            }
        }

        return [(index, context.Judge.Data(frame.Station, data.MoveToImmutable()))];
    }

    private IEnumerable<ReadItem> Pieces(ReadItem item)
    {
        for (var at = 0; at < item.Length; at += maxData)
        {
            yield return item with { Offset = item.Offset + at, Length = Math.Min(maxData, item.Length - at) };
        }
    }
}
