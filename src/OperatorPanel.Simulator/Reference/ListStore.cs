using System.Collections.Immutable;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Simulator.Reference;

/// <summary>
/// The READ lists in the tail of the handler's one 256-byte buffer, kept as the STL handler keeps them
/// (docs/protocol-v2.md, "Lists"): binary descriptors (AREA, OFFSET high, OFFSET low, LENGTH) packed downward from byte
/// 255 in definition order, and in the work bytes a start and count per list id plus the tail floor, the lowest start
/// (256 when no list is stored). Whatever reaches the floor has overwritten descriptors, so every list is cleared,
/// and with the lists their READ CHANGES copies.
/// </summary>
public sealed class ListStore
{
    private const int BufferBytes = HandlerMemory.BufferBytes;
    private readonly byte[] _buffer = new byte[BufferBytes];
    private readonly int[] _start = new int[ProtocolLimits.MaxLists + 1];
    private readonly int[] _count = new int[ProtocolLimits.MaxLists + 1];

    public ListStore(int copyBytes = HandlerMemory.DefaultCopyBytes)
    {
        Copies = new ListCopies(copyBytes);
    }

    /// <summary>The READ CHANGES copies of the stored lists.</summary>
    public ListCopies Copies { get; }

    /// <summary>The lowest buffer byte holding a descriptor; 256 when no list is stored.</summary>
    public int Floor { get; private set; } = BufferBytes;

    public bool IsDefined(int list) => list is >= 1 and <= ProtocolLimits.MaxLists && _count[list] > 0;

    /// <summary>Clears every list and drops every copy (invalidation, STOP, power-up, redefinition).</summary>
    public void Clear()
    {
        Array.Clear(_start);
        Array.Clear(_count);
        Floor = BufferBytes;
        Copies.Clear();
    }

    /// <summary>
    /// Clears every list when buffer bytes 1 .. <paramref name="lastByte"/> plus <paramref name="scratchBytes"/> below the
    /// floor (a READ's own descriptors) reach the floor.
    /// </summary>
    public void ClearIfReached(int lastByte, int scratchBytes = 0)
    {
        if (lastByte > Floor - 1 - scratchBytes)
        {
            Clear();
        }
    }

    /// <summary>
    /// The part of DEFINE LIST that comes before its item checks, once COUNT, body length and LIST have passed: an id
    /// already defined clears all lists; then the descriptors' ATH to just below the floor must not overlap its source
    /// (bytes 12 .. 11 + 8N): 11 + 8N &lt; F - 4N, else 04.
    /// </summary>
    public ProtocolError PrepareDefine(int list, int itemCount)
    {
        if (IsDefined(list))
        {
            Clear();
        }

        return 11 + (8 * itemCount) >= Floor - (4 * itemCount) ? ProtocolError.BadLength : ProtocolError.None;
    }

    /// <summary>
    /// Stores a checked DEFINE LIST (after <see cref="PrepareDefine"/>) under the capacity rule: every list's longest
    /// reply, the new one included (READ CHANGES FULL, 20 + 2D characters), must end before the new floor F - 4N, else
    /// 04 and nothing is stored. A stored list gets its copy if its D bytes fit in the copy bytes left.
    /// </summary>
    public ProtocolError Define(DefineListRequest define)
    {
        ArgumentNullException.ThrowIfNull(define);
        var n = define.Items.Length;
        var floor = Floor - (4 * n);
        var replies = Enumerable.Range(1, ProtocolLimits.MaxLists).Where(IsDefined).Select(DataBytes).Append(define.TotalLength);
        if (replies.Any(d => ProtocolLimits.ListReplyChars(d) > floor - 1))
        {
            return ProtocolError.BadLength;
        }

        for (var i = 0; i < n; i++)
        {
            var item = define.Items[i];
            var at = floor + (4 * i);
            (_buffer[at], _buffer[at + 1], _buffer[at + 2], _buffer[at + 3]) =
                ((byte)item.Area, (byte)(item.Offset >> 8), (byte)item.Offset, (byte)item.Length);
        }

        (_start[define.List], _count[define.List], Floor) = (floor, n, floor);
        Copies.Allocate(define.List, define.TotalLength);
        return ProtocolError.None;
    }

    /// <summary>The stored items of a defined list, read back from the buffer tail.</summary>
    public ImmutableArray<ReadItem> Items(int list) =>
        [.. Enumerable.Range(0, _count[list]).Select(i => _start[list] + (4 * i))
            .Select(at => new ReadItem((ProtocolArea)_buffer[at], (_buffer[at + 1] << 8) | _buffer[at + 2], _buffer[at + 3]))];

    /// <summary>D: the data bytes of a defined list.</summary>
    public int DataBytes(int list) => Items(list).Sum(i => i.Length);
}
