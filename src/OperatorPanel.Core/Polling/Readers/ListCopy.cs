using System.Collections.Immutable;

namespace OperatorPanel.Core.Polling.Readers;

/// <summary>
/// The PC's side of one stored list's change copy: the list's data as the PLC's copy holds it after the last good READ
/// CHANGES reply, 08 or 09 (default: unknown, so the next READ CHANGES must ask FULL), when the last FULL answer came,
/// and until when the list is read with READ LIST because the handler keeps no copy for it (it answered FULL unasked,
/// or REREAD with nothing changed).
/// </summary>
internal sealed class ListCopy
{
    public ImmutableArray<byte> Data { get; set; }

    public DateTimeOffset LastFull { get; set; }

    public DateTimeOffset ReadListUntil { get; set; }

    /// <summary>Whether the READ CHANGES in flight asked FULL.</summary>
    public bool AskedFull { get; set; }

    /// <summary>The data the PC held when a 09 answered the list REREAD, until the FULL answer that follows.</summary>
    public ImmutableArray<byte> BeforeReread { get; set; }

    /// <summary>
    /// Whether the FULL answer after a REREAD brought exactly the data held before it: then no byte changed, so the
    /// REREAD was not for too many changes (2K &gt;= D needs K &gt; 0; the K bytes alone always fit) but because the
    /// handler keeps no copy of the list (docs/protocol-v2.md, 09, case 1), and 09 would answer REREAD every cycle.
    /// </summary>
    public bool RereadWithoutChanges(ImmutableArray<byte> full) =>
        !BeforeReread.IsDefault && BeforeReread.AsSpan().SequenceEqual(full.AsSpan());

    /// <summary>
    /// Whether the list is "in step": an 08 READ CHANGES of it without FULL is allowed (docs/protocol-v2.md, 08 PC rules 1-3),
    /// so it may also go in a 09 MASK (09 PC rule 1): its last READ CHANGES brought a good answer and no FULL is due.
    /// </summary>
    public bool InStep(DateTimeOffset now, TimeSpan fullReadInterval) => !Data.IsDefault && now - LastFull < fullReadInterval;

    /// <summary>Protocol rule 2: after anything but a good reply the PLC's copy may have moved on; ask FULL next time.</summary>
    public void Forget() => Data = default;
}
