namespace OperatorPanel.Core.Protocol.V3;

/// <summary>
/// The sizes a v3 handler is generated with, which IDENTIFY reports and the PC plans by (docs/protocol.md section 6,
/// "The handler's V bytes"): the request buffer (the longest request, MAX_REQUEST) and, in the full handler, the list of
/// LIST_ITEMS slots holding at most LIST_BYTES data bytes. The V bytes follow from them; StlGen lays the handler out in
/// exactly these bytes and the reference model protects the same range.
/// </summary>
public sealed record HandlerShape(int RequestBytes, int ListItems, int ListBytes)
{
    /// <summary>Every handler's work bytes: step, flags, the check's sums, REQCHECK, pointers kept between scans.</summary>
    public const int WorkBytes = 40;

    /// <summary>The list's own work bytes: N, D, the groups in use, a pointer past the data in R, the slot DEFINE LIST stores next.</summary>
    public const int ListWorkBytes = 12;

    /// <summary>Slots are compared and gathered in groups of this many (one unrolled network each); a list has a whole number of groups.</summary>
    public const int GroupSlots = 8;

    /// <summary>
    /// The most bytes one item (one slot) reads, and the size of every slot's WINDOW (the bytes from its item's first
    /// byte that the handler compares with its copy in one double word compare).
    /// </summary>
    public const int ItemBytes = 4;

    /// <summary>Per slot: its destination pointer (in the reply), its source pointer, its length.</summary>
    public const int SlotBytes = 9;

    /// <summary>
    /// The full handler: a 137-byte buffer (a whole list reply of 128 data bytes; DEFINE LIST of 32 slots has 136) and a
    /// list of 32 slots, 128 data bytes.
    /// </summary>
    public static HandlerShape Full { get; } = new(137, 32, 128);

    /// <summary>
    /// The compact handler: IDENTIFY, READ, WRITE and WRITE BITS, no list, with the full handler's 137-byte buffer
    /// although its own frames have at most 33 bytes (IDENTIFY's reply; a WRITE of MAX_DATA, its longest request, has
    /// 28). The buffer is also the receive's maximum count (SMB94), and a receive ended by its count starts again at
    /// once: with 33 a '&lt;' in byte 34 or later of a longer frame on a shared bus (another station's DEFINE LIST, a list
    /// reply) started a receive of its tail, and a tail that was a frame for this station was answered, colliding with
    /// the addressed station's reply. At 137 no frame of the bus has a tail: 104 V bytes, no instruction.
    /// </summary>
    public static HandlerShape Compact { get; } = new(137, 0, 0);

    public bool HasList => ListItems > 0;

    /// <summary>The <see cref="Compact"/> or the <see cref="Full"/> shape, as a station's "compact" chooses.</summary>
    public static HandlerShape Of(bool compact) => compact ? Compact : Full;

    /// <summary>
    /// MAX_DATA: the data of one READ reply or WRITE request. 16 bytes: a WRITE's data and its read-back (two BMB of 16
    /// bytes, 0.7 ms) and the write checks stay within a scan's share; bulk reading is the list's job.
    /// </summary>
    public const int MaxData = 16;

    /// <summary>The copy: every slot's 4-byte window as the last READ LIST reported it.</summary>
    public int CopyBytes => ItemBytes * ListItems;

    /// <summary>
    /// V_BYTES: the buffer (with its count byte), work bytes, and with a list its work bytes, the copy and the slots.
    /// </summary>
    public int VBytes =>
        1 + RequestBytes + WorkBytes
        + (HasList ? ListWorkBytes + CopyBytes + (SlotBytes * ListItems) : 0);

    /// <summary>Where the generator puts the handler by default: the top of V, starting on an even byte.</summary>
    public int DefaultVFirst(int vAreaBytes) => (vAreaBytes - VBytes) & ~1;
}
