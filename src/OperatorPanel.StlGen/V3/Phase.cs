namespace OperatorPanel.StlGen.V3;

/// <summary>
/// Where OP_PANEL goes on in the next scan: one bit of the STEP word each (0 = no request), docs/protocol.md section 6.
/// Each phase is sized to stay within a scan's share (at most 2 ms with the interrupt routines, at the StlTiming
/// figures). A contact per phase finds it (0.37 us, and 46 us for its jump's test), in the order below: the most
/// frequent and the fullest phases first.
/// </summary>
internal enum Phase
{
    /// <summary>The request's or the reply's check, a few double words per scan (bit 1 below tells the reply's).</summary>
    Check = 0,

    /// <summary>With <see cref="Check"/>: the reply's check (the reply is sent meanwhile).</summary>
    ReplyFlag = 1,

    /// <summary>The next group of the list's items into R (a whole list's data).</summary>
    Gather = 2,

    /// <summary>Set by the receive routine: a request of LEN bytes for this station waits.</summary>
    Start = 3,
    Changes = 4,
    Reply = 5,
    Move = 6,
    Compare = 7,
    Dispatch = 8,

    /// <summary>DEFINE LIST: the next item's check.</summary>
    DefineSlot = 9,

    /// <summary>DEFINE LIST: the checked item's slot.</summary>
    DefineStore = 10,
}
