using System.Buffers.Binary;
using System.Collections.Immutable;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Protocol.V3;

namespace OperatorPanel.Simulator.Reference.V3;

/// <summary>Steps 3-5 of the processing order: the command's checks, in order, and its execution.</summary>
public sealed partial class ReferenceHandler
{
    /// <summary>
    /// The command's checks in order (docs/protocol.md section 4): an unknown command, or a payload length the command
    /// never has (IDENTIFY, READ LIST and READ LIST FULL 0, READ and STOP 4, WRITE BITS 5), is 85; then the command's own.
    /// </summary>
    private (ReplyStatus Status, ImmutableArray<byte> Payload) Answer(Command command, ReadOnlySpan<byte> p)
    {
        var list = Setup.Shape.HasList;
        return command switch
        {
            Command.Identify when p.Length == 0 => (ReplyStatus.Ok, Identify()),
            Command.Read when p.Length == 4 => Read(p),
            Command.Write => Write(p),
            Command.WriteBits when p.Length == 5 => WriteBits(p),
            Command.DefineList when list => Define(p),
            Command.ReadList or Command.ReadListFull when list && p.Length == 0 => ReadList(command == Command.ReadListFull),
            Command.Stop when Setup.AllowStop && p.Length == 4 => !p.SequenceEqual(Request.StopWord.AsSpan()) ? Refuse(ReplyStatus.BadParameter) : (ReplyStatus.Ok, []),
            _ => Refuse(ReplyStatus.UnknownCommand),
        };
    }

    private static (ReplyStatus, ImmutableArray<byte>) Refuse(ReplyStatus status) => (status, []);

    /// <summary>LENGTH 1 to MAX_DATA (84), then the item (82).</summary>
    private (ReplyStatus, ImmutableArray<byte>) Read(ReadOnlySpan<byte> p)
    {
        var item = ItemAt(p);
        var status = item.Length is 0 or > HandlerShape.MaxData ? ReplyStatus.BadLength : CheckItem(item);
        return status != ReplyStatus.Ok ? Refuse(status) : (ReplyStatus.Ok, [.. Memory.Area(item.Area).AsSpan(item.Offset, item.Length)]);
    }

    /// <summary>P = 4 + LENGTH, LENGTH 1 to MAX_DATA (84), then the item (82), then writable (83).</summary>
    private (ReplyStatus, ImmutableArray<byte>) Write(ReadOnlySpan<byte> p)
    {
        if (p.Length < 5 || p.Length != 4 + p[3] || p[3] > HandlerShape.MaxData)
        {
            return Refuse(ReplyStatus.BadLength);
        }

        var item = ItemAt(p);
        var status = CheckItem(item);
        status = status != ReplyStatus.Ok ? status : !IsWritable(item) ? ReplyStatus.NotWritable : ReplyStatus.Ok;
        if (status != ReplyStatus.Ok)
        {
            return Refuse(status);
        }

        var target = Memory.Area(item.Area).AsSpan(item.Offset, item.Length);
        p[4..].CopyTo(target);
        return (ReplyStatus.Ok, [.. target]);
    }

    private (ReplyStatus, ImmutableArray<byte>) WriteBits(ReadOnlySpan<byte> p)
    {
        var item = new ReadItem((ProtocolArea)p[0], BinaryPrimitives.ReadUInt16BigEndian(p[1..]), 1);
        var status = CheckItem(item);
        status = status != ReplyStatus.Ok ? status : !IsWritable(item) ? ReplyStatus.NotWritable : ReplyStatus.Ok;
        if (status != ReplyStatus.Ok)
        {
            return Refuse(status);
        }

        // The bits outside MASK stay as the program left them; the byte is stored once, as the handler's XORB does, so
        // the soak's observer sees one change for one WRITE BITS here too.
        var area = Memory.Area(item.Area);
        area[item.Offset] = (byte)((area[item.Offset] & ~p[3]) | (p[4] & p[3]));
        return (ReplyStatus.Ok, [area[item.Offset]]);
    }

    /// <summary>
    /// N items of 4 bytes, N a whole number of groups up to LIST_ITEMS (84); each item: LENGTH 1-4 (84), then area and
    /// its slot's WINDOW, the 4 bytes from OFFSET, inside the area (82). The old list is gone from the start: a refused DEFINE LIST leaves none.
    /// </summary>
    private (ReplyStatus, ImmutableArray<byte>) Define(ReadOnlySpan<byte> p)
    {
        List.Clear();
        if (p.Length == 0 || p.Length % (4 * HandlerShape.GroupSlots) != 0 || p.Length / 4 > Setup.Shape.ListItems)
        {
            return Refuse(ReplyStatus.BadLength);
        }

        var items = new ReadItem[p.Length / 4];
        for (var i = 0; i < items.Length; i++)
        {
            items[i] = ItemAt(p[(4 * i)..]);
            var status = items[i].Length is 0 or > HandlerShape.ItemBytes ? ReplyStatus.BadLength : CheckItem(items[i] with { Length = HandlerShape.ItemBytes });
            if (status != ReplyStatus.Ok)
            {
                return Refuse(status);
            }
        }

        List.Define(items);
        return (ReplyStatus.Ok, []);
    }

    /// <summary>
    /// 07: the whole list (each item's LENGTH bytes); the copy is not valid afterwards. 06: each slot's window (4 bytes
    /// from OFFSET) against its copy; the copy takes every window (it is what the reply reports); the whole list when the
    /// copy was not valid; else UNCHANGED when no window differed, CHANGES (slot, window) when the 5-byte entries of the
    /// differing slots are fewer bytes than the data, else the whole list.
    /// </summary>
    private (ReplyStatus, ImmutableArray<byte>) ReadList(bool full)
    {
        if (List.Count == 0)
        {
            return Refuse(ReplyStatus.ListNotDefined);
        }

        var data = Gather();
        if (full)
        {
            List.Invalidate();
            return (ReplyStatus.Ok, [.. data]);
        }

        var valid = List.CopyValid;
        var windows = Windows();
        var copy = List.Copy.ToArray();
        var changed = !valid ? [] : Enumerable.Range(0, List.Count).Where(k => !windows.AsSpan(4 * k, 4).SequenceEqual(copy.AsSpan(4 * k, 4))).ToList();
        List.Renew(windows);
        if (!valid)
        {
            return (ReplyStatus.Ok, [.. data]);
        }

        if (changed.Count == 0)
        {
            return (ReplyStatus.Unchanged, []);
        }

        return Limits.ChangeEntryBytes * changed.Count < List.DataBytes
            ? (ReplyStatus.Changes, [.. changed.SelectMany(k => windows.AsSpan(4 * k, 4).ToArray().Prepend((byte)k))])
            : (ReplyStatus.Ok, [.. data]);
    }

    /// <summary>The list data: each item's bytes, one after the other.</summary>
    private byte[] Gather() => [.. List.Items.SelectMany(i => Memory.Area(i.Area).AsSpan(i.Offset, i.Length).ToArray())];

    /// <summary>Each slot's window: the 4 bytes from its item's OFFSET.</summary>
    private byte[] Windows() => [.. List.Items.SelectMany(i => Memory.Area(i.Area).AsSpan(i.Offset, HandlerShape.ItemBytes).ToArray())];

    /// <summary>
    /// Area I, Q, M or V (82: SM, 05, is not served, docs/protocol.md section 1.3), then OFFSET + LENGTH within it (82);
    /// LENGTH (1 or more) checked before.
    /// </summary>
    private ReplyStatus CheckItem(ReadItem item)
    {
        if (item.Area is not (ProtocolArea.I or ProtocolArea.Q or ProtocolArea.M or ProtocolArea.V))
        {
            return ReplyStatus.AddressOutOfRange;
        }

        return item.Offset + item.Length > Memory.Area(item.Area).Length ? ReplyStatus.AddressOutOfRange : ReplyStatus.Ok;
    }

    private bool IsWritable(ReadItem item)
    {
        if (!Setup.MayWrite(item.Area))
        {
            return false;
        }

        for (var i = item.Offset; i < item.Offset + item.Length; i++)
        {
            if (item.Area == ProtocolArea.V && Setup.IsHandlerVByte(i))
            {
                return false;
            }
        }

        return true;
    }

    private static ReadItem ItemAt(ReadOnlySpan<byte> p) => new((ProtocolArea)p[0], BinaryPrimitives.ReadUInt16BigEndian(p[1..]), p[3]);
}
