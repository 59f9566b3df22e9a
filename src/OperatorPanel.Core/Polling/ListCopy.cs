using System.Collections.Immutable;

namespace OperatorPanel.Core.Polling;

/// <summary>
/// The PC's side of one stored list's change copy: the list's data as the PLC's copy holds it after the last good READ
/// CHANGES reply (default: unknown, so the next READ CHANGES must ask FULL), when the last FULL answer came, and until
/// when the list is read with READ LIST because the handler answered FULL unasked (it keeps no copy for it).
/// </summary>
internal sealed class ListCopy
{
    public ImmutableArray<byte> Data { get; set; }

    public DateTimeOffset LastFull { get; set; }

    public DateTimeOffset ReadListUntil { get; set; }

    /// <summary>Whether the READ CHANGES in flight asked FULL.</summary>
    public bool AskedFull { get; set; }

    /// <summary>Protocol rule 2: after anything but a good reply the PLC's copy may have moved on; ask FULL next time.</summary>
    public void Forget() => Data = default;
}
