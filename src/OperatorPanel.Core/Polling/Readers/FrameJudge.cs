using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Core.Polling.Readers;

/// <summary>
/// Turns what an exchange brought for a frame into its <see cref="FrameRead"/> and the station's state
/// (<see cref="StationTracker"/>): data, a refusal, a reply that does not fit, or a link failure. Every reader judges
/// here, so a failure keeps one form and one wording from the link to the values' qualities.
/// </summary>
internal sealed class FrameJudge(StationTracker stations)
{
    public StationTracker Stations => stations;

    public FrameRead Data(Station station, ImmutableArray<byte> data)
    {
        stations.RecordReply(station);
        return FrameRead.Success(data);
    }

    /// <summary>No valid reply: the station goes offline (and its other frames wait for the next cycle) when nothing answered.</summary>
    public FrameRead Failed(Station station, Exception failure)
    {
        var (message, offline) = stations.RecordFailure(station, failure);
        return FrameRead.Failure(message, offline);
    }

    public FrameRead Refused(PollFrame frame, ErrorResponse refused)
    {
        ArgumentNullException.ThrowIfNull(refused);
        return Refusal(frame, $"{frame.Station} refused READ {Describe(frame)}: {refused.Error}");
    }

    /// <summary>A PPI item answered with a return code other than success: <paramref name="reason"/> in our words.</summary>
    public FrameRead Refused(PollFrame frame, string reason) => Refusal(frame, $"{frame.Station} refused reading {Describe(frame)}: {reason}");

    /// <summary>A reply came that does not fit the frame: the station answers, so it keeps its state.</summary>
    public FrameRead Unexpected(PollFrame frame, PlcResponse? response) => Unexpected(frame, Describe(response));

    /// <summary>A reply came that does not fit the frame (<paramref name="what"/> it brought): the station keeps its state.</summary>
    public FrameRead Unexpected(PollFrame frame, string what)
    {
        ArgumentNullException.ThrowIfNull(frame);
        var message = $"unexpected reply to READ {Describe(frame)}: {what}";
        stations.RecordBadReply(frame.Station, message);
        return FrameRead.Failure(message, stationOffline: false);
    }

    private FrameRead Refusal(PollFrame frame, string refusal)
    {
        ArgumentNullException.ThrowIfNull(frame);
        stations.RecordReply(frame.Station, refusal);
        return FrameRead.Refusal(refusal);
    }

    public static string Describe(PollFrame frame)
    {
        ArgumentNullException.ThrowIfNull(frame);
        return frame.PpiItem is { } item ? item.ToString() : string.Join(", ", frame.Items.Select(i => $"{i.Area}{i.Offset}+{i.Length}"));
    }

    public static string Describe(PlcResponse? response) => response switch
    {
        null => "no reply object",
        ReadResponse read => $"{read.Data.Length} data bytes",
        ReadListResponse list => $"{list.Data.Length} data bytes",
        ReadChangesResponse { Full: true } changes => $"FULL with {changes.Data.Length} data bytes",
        ReadChangesResponse changes => $"{changes.Changes.Length} changed bytes that do not fit the list",
        ReadChangesOfListsResponse lists => $"entries for lists {string.Join(", ", lists.Lists.Select(e => e.List))} whose changes do not fit them",
        ErrorResponse error => $"error {(byte)error.Error:X2} {error.Error}",
        _ => $"{response.GetType().Name}",
    };
}
