using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Simulator.Reference.V3;

/// <summary>
/// The station's one list (docs/protocol.md section 2, 05 DEFINE LIST): N items (a whole number of groups of 8), each
/// of 1-4 bytes, whose bytes follow one another in the list data (D bytes); and the copy of every slot's 4-byte window
/// READ LIST compares with, valid once a reply reported the list.
/// </summary>
public sealed class StationList
{
    private ReadItem[] _items = [];
    private byte[] _copy = [];

    /// <summary>N: the items of the list; 0 = no list.</summary>
    public int Count => _items.Length;

    /// <summary>D: the list data bytes every whole reply carries.</summary>
    public int DataBytes { get; private set; }

    public IReadOnlyList<ReadItem> Items => _items;

    /// <summary>The copy holds what the last READ LIST reply reported (after DEFINE LIST, 07, STOP or RUN/TERM it does not).</summary>
    public bool CopyValid { get; private set; }

    public ReadOnlySpan<byte> Copy => _copy;

    /// <summary>Forgets the list and the copy: a DEFINE LIST's start, STOP, the mode switch, the first scan.</summary>
    public void Clear()
    {
        (_items, DataBytes, CopyValid) = ([], 0, false);
    }

    /// <summary>The list from now on; the copy is not valid.</summary>
    public void Define(ReadItem[] items)
    {
        // The old copy goes with the old list: a shorter list's first READ LIST must not compare against it.
        (_items, DataBytes, CopyValid, _copy) = (items, items.Sum(i => i.Length), false, []);
    }

    /// <summary>07 READ LIST FULL: the copy is not valid (the next 06 answers the whole list).</summary>
    public void Invalidate() => CopyValid = false;

    /// <summary>The copy becomes <paramref name="data"/> (what the reply reports), valid.</summary>
    public void Renew(ReadOnlySpan<byte> data)
    {
        _copy = data.ToArray();
        CopyValid = true;
    }
}
