using System.Collections.Immutable;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Core.Polling;

/// <summary>
/// READ lists (docs/protocol.md, "Lists"): the plan's frames are the same every cycle, so each frame that fits is
/// stored in its station once with DEFINE LIST and then polled with a 12-character READ LIST. A station that lost its
/// lists (a long frame reached the buffer tail, STOP, power-up) answers 07: the frame is defined again and read once
/// more in the same cycle. A frame whose DEFINE is refused is read with plain READs from then on.
/// </summary>
public sealed partial class PollingEngine
{
    private readonly ImmutableDictionary<int, int> _listIds;
    private readonly HashSet<int> _definedFrames = [];
    private readonly HashSet<int> _plainFrames = [];

    /// <summary>
    /// Poll with DEFINE LIST / READ LIST (default) or with plain READs only, one exchange per frame and cycle. Set
    /// before <see cref="RunAsync"/>.
    /// </summary>
    public bool UseReadLists { get; init; } = true;

    /// <summary>READ LIST when the frame has a list (defining it first when needed), else a plain READ.</summary>
    private async Task<PlcResponse> ExchangeFrameAsync(int index, CancellationToken cancellationToken)
    {
        var frame = _plan.Frames[index];
        if (!UseReadLists || !_listIds.TryGetValue(index, out var list) || _plainFrames.Contains(index))
        {
            return await ReadPlainAsync(frame, cancellationToken).ConfigureAwait(false);
        }

        for (var attempt = 0; ; attempt++)
        {
            if (!_definedFrames.Contains(index) && !await DefineAsync(index, list, cancellationToken).ConfigureAwait(false))
            {
                return await ReadPlainAsync(frame, cancellationToken).ConfigureAwait(false);
            }

            var response = await _link.ExchangeAsync(new ReadListRequest(frame.Station, list), cancellationToken).ConfigureAwait(false);
            if (response is not ErrorResponse { Error: ProtocolError.ListNotDefined } || attempt > 0)
            {
                return response;
            }

            // The station lost its lists; define this one again and read once more, in this cycle.
            _definedFrames.Remove(index);
            _logger.Debug("{Station}: list {List} not defined (invalidated); defining it again", frame.Station.Address, list);
        }
    }

    /// <summary>True when the station stored the list; false (logged once) when it refused, and the frame goes back to plain READ.</summary>
    private async Task<bool> DefineAsync(int index, int list, CancellationToken cancellationToken)
    {
        var frame = _plan.Frames[index];
        var response = await _link.ExchangeAsync(new DefineListRequest(frame.Station, list, frame.Items), cancellationToken).ConfigureAwait(false);
        if (response is DefineListResponse)
        {
            _definedFrames.Add(index);
            return true;
        }

        _plainFrames.Add(index);
        _logger.Warning("{Station}: DEFINE LIST {List} ({Items}) not accepted ({Reply}); reading that frame with plain READ", frame.Station.Address, list, Describe(frame), Describe(response));
        return false;
    }

    private Task<PlcResponse> ReadPlainAsync(PollFrame frame, CancellationToken cancellationToken) =>
        _link.ExchangeAsync(new ReadRequest(frame.Station, frame.Items), cancellationToken);
}
