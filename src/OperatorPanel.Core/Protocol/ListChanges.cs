using System.Collections.Immutable;

namespace OperatorPanel.Core.Protocol;

/// <summary>
/// One entry of a READ CHANGES OF LISTS reply: list <paramref name="List"/>'s changed bytes since the handler's copy
/// (none when idle), or <paramref name="Reread"/> (K = 16#FE): its changes are not in the reply, the handler's copy of
/// it is now invalid, and the PC reads it with 08 READ CHANGES (answered FULL).
/// </summary>
public sealed record ListChanges(int List, bool Reread, ImmutableArray<ChangedByte> Changes)
{
    public static ListChanges Pairs(int list, ImmutableArray<ChangedByte> changes) => new(list, false, changes);

    public static ListChanges RereadList(int list) => new(list, true, []);

    /// <summary>
    /// The list's data now: <paramref name="previous"/> (what the PC holds from its last good reply of this list) with
    /// the changes applied. False for a REREAD entry, or when a change's index lies outside the data.
    /// </summary>
    public bool TryApply(ReadOnlySpan<byte> previous, out ImmutableArray<byte> current)
    {
        current = default;
        return !Reread && ChangedByte.TryApply(previous, Changes, out current);
    }

    public bool Equals(ListChanges? other) =>
        other is not null && List == other.List && Reread == other.Reread && Changes.AsSpan().SequenceEqual(other.Changes.AsSpan());

    public override int GetHashCode() => HashCode.Combine(List, Reread, Changes.Length);
}
