namespace OperatorPanel.Core.Protocol.V3;

/// <summary>
/// Cuts a byte stream that arrives in arbitrary pieces into v3 frames by their LEN, as a radio module does
/// (docs/protocol.md section 1.6): bytes before '&lt;' are noise; '&lt;' then LEN, and the frame ends after LEN bytes in all,
/// whatever values they hold ('&lt;' and '&gt;' included). A LEN below the shortest frame's is noise: the reader
/// hunts for the next '&lt;' after that '&lt;'. Frames come out whole and unchecked. Not thread-safe: one per port.
/// </summary>
public sealed class Reader(int minLen = Codec.MinReplyLen)
{
    private readonly List<byte> _partial = new(Limits.MaxFrameBytes);
    private readonly Queue<byte[]> _ready = new();

    /// <summary>Bytes of an unfinished frame held so far.</summary>
    public int PendingBytes => _partial.Count;

    /// <summary>Bytes dropped as noise (before a '&lt;', or a '&lt;' with an impossible LEN) since the last <see cref="Reset"/>.</summary>
    public int SkippedBytes { get; private set; }

    public void Append(ReadOnlySpan<byte> bytes)
    {
        foreach (var b in bytes)
        {
            Accept(b);
        }
    }

    public bool TryTake(out byte[] frame) => _ready.TryDequeue(out frame!);

    /// <summary>Forgets a partial frame and every untaken frame, e.g. after a timeout.</summary>
    public void Reset()
    {
        _partial.Clear();
        _ready.Clear();
        SkippedBytes = 0;
    }

    private void Accept(byte b)
    {
        if (_partial.Count == 0)
        {
            if (b == Limits.Start)
            {
                _partial.Add(b);
            }
            else
            {
                SkippedBytes++;
            }

            return;
        }

        if (_partial.Count == 1 && (b < minLen))
        {
            SkippedBytes++;
            _partial.Clear();
            Accept(b);
            return;
        }

        _partial.Add(b);
        if (_partial.Count == _partial[1])
        {
            _ready.Enqueue([.. _partial]);
            _partial.Clear();
        }
    }
}
