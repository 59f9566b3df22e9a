using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Simulator.Reference;

/// <summary>
/// The READ CHANGES copies (docs/protocol-v2.md, "08 READ CHANGES"): COPY_BYTES V bytes after the work bytes, handed to
/// the lists in definition order. A list whose data does not fit in what is left gets no copy and is always answered
/// FULL. A new copy is not valid until a FULL answer has filled it, and not after a 09 REREAD entry. Cleared with the lists.
/// </summary>
public sealed class ListCopies
{
    private readonly byte[] _bytes;
    private readonly int[] _start = new int[ProtocolLimits.MaxLists + 1];
    private readonly bool[] _valid = new bool[ProtocolLimits.MaxLists + 1];
    private int _free;

    public ListCopies(int copyBytes)
    {
        _bytes = new byte[copyBytes];
        Clear();
    }

    /// <summary>Copy bytes not yet handed to a list.</summary>
    public int FreeBytes => _bytes.Length - _free;

    public bool HasCopy(int list) => _start[list] >= 0;

    public bool IsValid(int list) => _valid[list];

    public void Clear()
    {
        Array.Fill(_start, -1);
        Array.Clear(_valid);
        _free = 0;
    }

    /// <summary>Gives a just-defined list of <paramref name="dataBytes"/> its copy, not yet valid, if it fits.</summary>
    public void Allocate(int list, int dataBytes)
    {
        _valid[list] = false;
        if (dataBytes <= FreeBytes)
        {
            _start[list] = _free;
            _free += dataBytes;
        }
    }

    /// <summary>The copy's bytes (only for a list that <see cref="HasCopy"/>).</summary>
    public Span<byte> Of(int list, int dataBytes) => _bytes.AsSpan(_start[list], dataBytes);

    /// <summary>A 09 entry REREAD: whatever the copy holds, the next READ CHANGES of the list answers FULL.</summary>
    public void Invalidate(int list) => _valid[list] = false;

    /// <summary>The copy now holds what the reply reports: valid from here on.</summary>
    public void Renew(int list, ReadOnlySpan<byte> data)
    {
        data.CopyTo(Of(list, data.Length));
        _valid[list] = true;
    }
}
