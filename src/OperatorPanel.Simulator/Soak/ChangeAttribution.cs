using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Simulator.Soak;

/// <summary>
/// Names what made each change the <see cref="ExecutedWriteObserver"/> saw. A change of Q, M or V is a panel write's:
/// the last write handed to the bus before the change (the one in flight, as the soak has one at a time; else an
/// earlier one executed late) that explains it, that is, whose bytes hold all of the change and now hold exactly that
/// write's value, or for a bit, whose byte changed in that bit alone, to the write's value. Words and double words carry
/// a value no other write of the run has, so such a change names its write whenever it came; a byte or bit value
/// recurs, so a late byte or bit write that stores what the write in flight also stores is taken for that one.
/// One write is one change: WRITE stores its data with one BMB and WRITE BITS its byte with one XORB (since
/// 2026-11-28; the AND-then-OR form stored it twice), so a bit seen cleared and set again is two changes, each judged
/// on its own, and a 0 no write carried is a change nothing explains.
/// A change of I or SM is the field's (<see cref="SoakField"/>) when it leaves the bytes the field's latest setting
/// before it put there.
/// </summary>
internal static class ChangeAttribution
{
    /// <summary>The write that explains <paramref name="change"/> (applied to <paramref name="after"/>), or null.</summary>
    public static SoakWrite? WriteOf(IReadOnlyList<SoakWrite> writes, MemoryChange change, MemoryImage after)
    {
        for (var k = writes.Count - 1; k >= 0; k--)
        {
            if (writes[k].Sent <= change.Timestamp && Explains(writes[k], change, after))
            {
                return writes[k];
            }
        }

        return null;
    }

    /// <summary>True when the field's latest setting of the change's area before it left exactly the changed bytes.</summary>
    public static bool IsFields(IReadOnlyList<MemoryChange> settings, MemoryChange change)
    {
        var latest = settings.LastOrDefault(s => s.Area == change.Area && s.Timestamp <= change.Timestamp);
        return latest is not null && latest.First <= change.First && latest.Last >= change.Last
            && latest.After.AsSpan(change.First - latest.First, change.After.Length).SequenceEqual(change.After.AsSpan());
    }

    private static bool Explains(SoakWrite write, MemoryChange change, MemoryImage after)
    {
        var address = write.Address;
        if (SoakRegion.AreaOf(address) != change.Area || change.First < address.ByteOffset || change.Last > address.LastByte)
        {
            return false;
        }

        if (address.Bit is { } bit && (change.Before[0] ^ change.After[0]) != 1 << bit)
        {
            return false;
        }

        return after.Read(address).AsSpan().SequenceEqual(write.Value.AsSpan());
    }

    /// <summary>I and SM: areas the Freeport link never writes; only the field changes them.</summary>
    public static bool IsFieldArea(ProtocolArea area) => area is ProtocolArea.I or ProtocolArea.SM;
}
