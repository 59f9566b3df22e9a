using System.Collections.Immutable;

namespace OperatorPanel.Core.Protocol;

/// <summary>One INDEX VALUE pair of a READ CHANGES reply: byte <paramref name="Index"/> of the list's data is now <paramref name="Value"/>.</summary>
public readonly record struct ChangedByte(byte Index, byte Value)
{
    /// <summary>
    /// <paramref name="previous"/> (what the PC holds from its last good reply of the list) with
    /// <paramref name="changes"/> applied. False when a change's index lies outside it.
    /// </summary>
    public static bool TryApply(ReadOnlySpan<byte> previous, ImmutableArray<ChangedByte> changes, out ImmutableArray<byte> current)
    {
        var bytes = previous.ToArray();
        current = default;
        foreach (var change in changes)
        {
            if (change.Index >= bytes.Length)
            {
                return false;
            }

            bytes[change.Index] = change.Value;
        }

        current = [.. bytes];
        return true;
    }
}
