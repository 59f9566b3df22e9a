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

    /// <summary>The list's own work bytes: N, D, the groups in use, the group being gathered, pointers past the data and to the next slot.</summary>
    public const int ListWorkBytes = 12;

    /// <summary>Slots are gathered in groups of this many, one group per scan; a list has a whole number of groups.</summary>
    public const int GroupSlots = 8;

    /// <summary>The most bytes one item (one slot) reads: a group of 8 slots then moves at most 32 bytes.</summary>
    public const int ItemBytes = 4;

    /// <summary>Per slot: its destination pointer, its source pointer, its length.</summary>
    public const int SlotBytes = 9;

    /// <summary>
    /// The full handler: a 136-byte request buffer (DEFINE LIST of 32 slots; a CHANGES reply of the largest list) and a
    /// list of 32 slots, 128 data bytes.
    /// </summary>
    public static HandlerShape Full { get; } = new(136, 32, 128);

    /// <summary>
    /// The compact handler: IDENTIFY, READ, WRITE and WRITE BITS, no list, with a 33-byte buffer: the longest reply,
    /// IDENTIFY's (a WRITE of MAX_DATA, the longest request, has 28 bytes).
    /// </summary>
    public static HandlerShape Compact { get; } = new(33, 0, 0);

    public bool HasList => ListItems > 0;

    /// <summary>
    /// MAX_DATA: the data of one READ reply or WRITE request. 16 bytes: a WRITE's data and its read-back (two BMB of 16
    /// bytes, 0.7 ms) and the write checks stay within a scan's share; bulk reading is the list's job.
    /// </summary>
    public const int MaxData = 16;

    /// <summary>
    /// The list reply area: count byte, the 5 head bytes, the gathered data (LIST_BYTES), and 4 bytes where a whole
    /// list's check goes (zeroed before each gather: the check reads whole double words).
    /// </summary>
    public int ListReplyBytes => HasList ? 1 + Limits.ReplyHead + ListBytes + WordCheck.Bytes : 0;

    /// <summary>
    /// V_BYTES: request buffer (with its count byte), work bytes, and with a list its reply area, copy, slots (and the
    /// destination pointer after the last, where the data ends) and work bytes.
    /// </summary>
    public int VBytes =>
        1 + RequestBytes + WorkBytes
        + (HasList ? ListReplyBytes + ListBytes + (SlotBytes * ListItems) + 4 + ListWorkBytes : 0);

    /// <summary>Where the generator puts the handler by default: the top of V, starting on an even byte.</summary>
    public int DefaultVFirst(int vAreaBytes) => (vAreaBytes - VBytes) & ~1;
}
