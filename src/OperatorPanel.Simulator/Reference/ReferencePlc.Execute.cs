using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Simulator.Reference;

/// <summary>Step 7's execution: the reply payload after STATUS and REQCHECK.</summary>
public sealed partial class ReferencePlc
{
    /// <summary>
    /// Executes a parsed request. A request this model does not execute (a command added to the protocol and not yet
    /// here) is refused with 05 unknown command, as docs/protocol-v2.md section 3 says of a CMD the handler does not have;
    /// it is never answered as another command.
    /// </summary>
    internal ProtocolError TryExecute(PlcRequest request, out byte[] payload)
    {
        var executed = Execute(request);
        payload = executed ?? [];
        return executed is null ? ProtocolError.UnknownCommand : ProtocolError.None;
    }

    /// <summary>The payload; null for a request this model does not execute.</summary>
    private byte[]? Execute(PlcRequest request)
    {
        switch (request)
        {
            case IdentifyRequest:
                return Identify();
            case ReadRequest read:
                return ReadItems(read.Items);
            case ReadListRequest list:
                return ReadItems(_lists.Items(list.List));
            case ReadChangesRequest changes:
                return ReadChanges(changes);
            case ReadChangesOfListsRequest lists:
                return ReadChangesOfLists(lists);
            case DefineListRequest or StopRequest:
                return [];
            case WriteBlockRequest write:
                write.Data.CopyTo(Memory.Area(write.Area), write.Offset);
                if (write.Area == ProtocolArea.Q)
                {
                    _panelOwnedOutputs.AsSpan(write.Offset, write.Data.Length).Fill(0xFF);
                }

                return Memory.Area(write.Area).AsSpan(write.Offset, write.Data.Length).ToArray();
            case WriteBitRequest bit:
                // ORB / ANDB on the byte itself: the other seven bits stay as the program left them.
                Memory.SetBit(bit.Area, bit.Offset, bit.Bit, bit.Value);
                if (bit.Area == ProtocolArea.Q)
                {
                    _panelOwnedOutputs[bit.Offset] |= (byte)(1 << bit.Bit);
                }

                return [Memory.Area(bit.Area)[bit.Offset]];
            default:
                return null;
        }
    }

    /// <summary>
    /// K = 16#FF and the whole data when FULL is asked, the list has no copy or no valid one, or the pairs would not be
    /// shorter (2K &gt;= D); else K pairs INDEX VALUE, ascending. Either way the copy (if the list has one) now holds
    /// the data just read.
    /// </summary>
    private byte[] ReadChanges(ReadChangesRequest request)
    {
        var data = ReadItems(_lists.Items(request.List));
        var copies = _lists.Copies;
        if (!copies.HasCopy(request.List))
        {
            return [ProtocolLimits.FullListMarker, .. data];
        }

        var changed = Enumerable.Range(0, data.Length).Where(i => data[i] != copies.Of(request.List, data.Length)[i]).ToList();
        var full = request.Full || !copies.IsValid(request.List) || 2 * changed.Count >= data.Length;
        copies.Renew(request.List, data);
        return full
            ? [ProtocolLimits.FullListMarker, .. data]
            : [(byte)changed.Count, .. changed.SelectMany(i => new[] { (byte)i, data[i] })];
    }

    /// <summary>
    /// One entry per list in MASK, ascending: K pairs exactly as 08 answers them, the copy renewed; or REREAD (16#FE)
    /// with the copy invalid when the list has no valid copy, its pairs would not be shorter (2K &gt;= D), or would not
    /// fit: the reply with them, and one K byte for each later list, must end before LAST_FREE (= floor - 1).
    /// </summary>
    private byte[] ReadChangesOfLists(ReadChangesOfListsRequest request)
    {
        var copies = _lists.Copies;
        var payload = new List<byte>();
        for (var n = 0; n < request.Lists.Count; n++)
        {
            var list = request.Lists[n];
            if (!copies.HasCopy(list) || !copies.IsValid(list))
            {
                payload.Add(ProtocolLimits.RereadListMarker);
                continue;
            }

            var data = ReadItems(_lists.Items(list));
            var copy = copies.Of(list, data.Length).ToArray();
            var changed = Enumerable.Range(0, data.Length).Where(i => data[i] != copy[i]).ToList();
            var later = request.Lists.Count - n - 1;
            var fits = ProtocolLimits.ReplyChars(payload.Count + 1 + (2 * changed.Count) + later) <= _lists.Floor - 1;
            copies.Renew(list, data);
            if (2 * changed.Count >= data.Length || !fits)
            {
                copies.Invalidate(list);
                payload.Add(ProtocolLimits.RereadListMarker);
                continue;
            }

            payload.Add((byte)changed.Count);
            payload.AddRange(changed.SelectMany(i => new[] { (byte)i, data[i] }));
        }

        return [.. payload];
    }

    private byte[] ReadItems(IEnumerable<ReadItem> items) =>
        [.. items.SelectMany(item => Memory.Area(item.Area).Skip(item.Offset).Take(item.Length))];

    private byte[] Identify() =>
    [
        HandlerIdentity.ProtocolVersion,
        HandlerIdentity.HandlerRevision,
        HandlerIdentity.CpuModelCode(Config.Cpu.Model),
        HandlerIdentity.CpuRevisionCode(Config.Cpu.Revision),
        Config.WriteMask,
        HandlerIdentity.MaxReadData,
        Config.ReplyDelayMs,
        Memory.SM[Smb6],
        Memory.GetBit(ProtocolArea.SM, 0, 7) ? HandlerIdentity.ModeSwitchRunFlag : (byte)0,
        .. Memory.SM.AsSpan(Smw22, 6),
        (byte)Config.Port,
        (byte)(Config.BufferStart >> 8),
        (byte)Config.BufferStart,
        (byte)(Config.HandlerVBytes >> 8),
        (byte)Config.HandlerVBytes,
        (byte)((Config.AllowStop ? HandlerIdentity.StopFeature : 0) | (Config.CopyBytes > 0 ? HandlerIdentity.CopiesFeature : 0)
            | HandlerIdentity.ChangesOfListsFeature),
        (byte)Config.CopyBytes,
    ];
}
