using OperatorPanel.Core.Link;
using OperatorPanel.Core.Ppi;
using OperatorPanel.Core.Ppi.S7;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Core.Polling.Readers;

/// <summary>
/// S7 read-var over PPI (docs/ppi.md sections 5-8): a PPI bus's plan has one frame per S7 item (PpiPollPlanner); this
/// reader packs the pending frames of a station into one job while the job and its answer fit the PDU and the item
/// limit, as the planner did. An item answered with a return code other than 16#FF refuses only its own frame (its
/// values turn bad with the code's text); a failed job fails every frame it carried, and the station's state follows.
/// The only reader of every station of a PPI bus (<see cref="ReaderChoice"/>).
/// </summary>
internal sealed class PpiReader(PollingContext context, PpiLink link) : IStationReader
{
    public async Task<IReadOnlyList<(int Frame, FrameRead Read)>> ReadAsync(IReadOnlyList<int> pending, CancellationToken cancellationToken)
    {
        ArgumentNullException.ThrowIfNull(pending);
        var station = context.Plan.Frames[pending[0]].Station;
        var taken = new List<int>();
        var items = new List<S7Item>();
        foreach (var index in pending)
        {
            items.Add(context.Plan.Frames[index].PpiItem!.Value);
            if (items.Count > PpiLimits.Default.MaxReadItems || S7AnswerCodec.ReadAnswerLength(items) > PpiLimits.Default.PduSize)
            {
                items.RemoveAt(items.Count - 1);
                break;
            }

            taken.Add(index);
        }

        try
        {
            var results = await link.ReadAsync(station, items, cancellationToken).ConfigureAwait(false);
            return [.. taken.Select((index, i) => (index, Judge(context.Plan.Frames[index], results[i])))];
        }
        catch (PlcCommunicationException failure)
        {
            var read = context.Judge.Failed(station, failure);
            return [.. taken.Select(index => (index, read))];
        }
    }

    private FrameRead Judge(PollFrame frame, S7ItemResult result) => result switch
    {
        { Succeeded: true } when result.Data.Length == frame.DataBytes => context.Judge.Data(frame.Station, result.Data),
        { Succeeded: true } => context.Judge.Unexpected(frame, $"{result.Data.Length} data bytes"),
        _ => context.Judge.Refused(frame, S7ReturnCodeText.Describe(result.Code)),
    };
}
