using System.Collections.Immutable;

namespace OperatorPanel.Core.Protocol;

/// <summary>
/// Cuts a byte stream that arrives in arbitrary pieces into frames. Bytes before '&lt;' are noise; a '&lt;' inside a
/// frame starts it again (the sender gave up on the old one); 255 characters without '&gt;' are reported as
/// <see cref="FrameError.TooLong"/> and the reader hunts for the next '&lt;'. Not thread-safe: one reader per port.
/// </summary>
public sealed class FrameReader
{
    private readonly List<byte> _partial = new(ProtocolLimits.MaxFrameChars);
    private readonly Queue<FrameReadResult> _ready = new();
    private int _skipped;

    /// <summary>Characters of an unfinished frame held so far.</summary>
    public int PendingChars => _partial.Count;

    public void Append(ReadOnlySpan<byte> bytes)
    {
        foreach (var b in bytes)
        {
            Accept(b);
        }
    }

    public bool TryTake(out FrameReadResult result) => _ready.TryDequeue(out result);

    /// <summary>Forgets a partial frame and every untaken result, e.g. after a timeout.</summary>
    public void Reset()
    {
        _partial.Clear();
        _ready.Clear();
        _skipped = 0;
    }

    private void Accept(byte b)
    {
        if (b == FrameCodec.StartChar)
        {
            _skipped += _partial.Count;
            _partial.Clear();
            _partial.Add(b);
            return;
        }

        if (_partial.Count == 0)
        {
            _skipped++;
            return;
        }

        _partial.Add(b);
        if (b == FrameCodec.EndChar)
        {
            Emit(new FrameReadResult([.. _partial], FrameError.None, _skipped));
        }
        else if (_partial.Count == ProtocolLimits.MaxFrameChars)
        {
            Emit(new FrameReadResult(ImmutableArray<byte>.Empty, FrameError.TooLong, _skipped));
        }
    }

    private void Emit(FrameReadResult result)
    {
        _ready.Enqueue(result);
        _partial.Clear();
        _skipped = 0;
    }
}
