using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Simulator.Reference;

/// <summary>Steps 5-7 of the processing order: a frame for this station that passed its check.</summary>
public sealed partial class ReferencePlc
{
    private byte[] Answer(FreeportFrame frame, ushort check, out bool stops)
    {
        stops = false;

        // Step 5: STOP is an unknown command in a handler generated without it.
        if (frame.Command == (byte)CommandCode.Stop && !Config.AllowStop)
        {
            return Reply(frame, check, ProtocolError.UnknownCommand, []);
        }

        // Step 6. A READ whose descriptors, ATH'd just below the floor, would overlap their source clears the lists.
        if (ReadCount(frame) is { } n)
        {
            _lists.ClearIfReached(9 + (8 * n), 4 * n);
        }

        // DEFINE LIST: a defined id clears all lists, and its descriptors' ATH must fit below the floor, before the items.
        if (DefineHeader(frame) is { } header && _lists.PrepareDefine(header.List, header.Count) is var refused && refused != ProtocolError.None)
        {
            return Reply(frame, check, refused, []);
        }

        if (!RequestCodec.TryParse(frame, this, out var request, out var error))
        {
            return Reply(frame, check, error, []);
        }

        error = request switch
        {
            DefineListRequest define => _lists.Define(define),
            ReadListRequest list when !_lists.IsDefined(list.List) => ProtocolError.ListNotDefined,
            ReadChangesRequest changes when !_lists.IsDefined(changes.List) => ProtocolError.ListNotDefined,
            ReadChangesOfListsRequest lists when !lists.Lists.All(_lists.IsDefined) => ProtocolError.ListNotDefined,
            _ => ProtocolError.None,
        };
        if (error != ProtocolError.None)
        {
            return Reply(frame, check, error, []);
        }

        // Step 7: execute; the caller sends the reply after the configured delay. A reply (18 + 2P characters) that
        // would reach the floor, or a READ's descriptors below it, clears every list first. READ LIST and READ CHANGES
        // replies stay within the capacity rule, READ CHANGES OF LISTS replies within LAST_FREE by their REREAD rule;
        // STOP's reply (18 characters) is shorter than any list's.
        error = TryExecute(request, out var payload);
        if (error != ProtocolError.None)
        {
            return Reply(frame, check, error, []);
        }

        if (request is not (ReadListRequest or ReadChangesRequest or ReadChangesOfListsRequest or DefineListRequest))
        {
            _lists.ClearIfReached(ProtocolLimits.ReplyChars(payload.Length), request is ReadRequest read ? 4 * read.Items.Length : 0);
        }

        stops = request is StopRequest;
        return Reply(frame, check, ProtocolError.None, [.. payload]);
    }

    /// <summary>LIST and COUNT of a DEFINE LIST whose COUNT, body length and LIST passed (step 6 up to the items).</summary>
    private static (int List, int Count)? DefineHeader(FreeportFrame frame) =>
        frame.Command == (byte)CommandCode.DefineList && frame.BodyBytes >= 5 && frame.Payload[1] is >= 1 and <= ProtocolLimits.MaxReadItems
            && frame.BodyBytes == 5 + (4 * frame.Payload[1]) && frame.Payload[0] is >= 1 and <= ProtocolLimits.MaxLists
            ? (frame.Payload[0], frame.Payload[1]) : null;

    /// <summary>COUNT of a READ whose COUNT and body length passed: the handler ATHs its descriptors now.</summary>
    private static int? ReadCount(FreeportFrame frame) =>
        frame.Command == (byte)CommandCode.Read && frame.BodyBytes >= 4 && frame.Payload[0] is >= 1 and <= ProtocolLimits.MaxReadItems
            && frame.BodyBytes == 4 + (4 * frame.Payload[0]) ? frame.Payload[0] : null;
}
