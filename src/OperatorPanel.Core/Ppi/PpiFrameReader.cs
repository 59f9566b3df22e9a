namespace OperatorPanel.Core.Ppi;

/// <summary>
/// Cuts the characters of a PPI line, arriving in arbitrary pieces, into FDL telegrams (docs/ppi.md section 2). Outside
/// a telegram, 16#E5 is a short acknowledge, 16#10, 16#68 and 16#DC start the fixed, variable and token formats, and
/// anything else is noise. A telegram is taken whole by its format's length, so 16#E5 or 16#16 inside its data are
/// data. A broken SD2 header is dropped by one character and the rest searched again; a telegram of full length with a
/// wrong check or end is dropped whole (searching inside it could find a phantom 16#E5). Not thread-safe: one reader
/// per port.
/// </summary>
public sealed class PpiFrameReader
{
    private readonly List<byte> _partial = new(PpiFrameCodec.MaxData + PpiFrameCodec.VariableOverhead);
    private readonly Queue<PpiReadResult> _ready = new();
    private int _expected;
    private int _skipped;

    /// <summary>Characters of an unfinished telegram held so far.</summary>
    public int PendingChars => _partial.Count;

    /// <summary>Characters still missing from the unfinished telegram, as far as its header tells (0 when none is begun).</summary>
    public int MissingChars => _partial.Count == 0 ? 0 : _expected - _partial.Count;

    public void Append(ReadOnlySpan<byte> bytes)
    {
        foreach (var b in bytes)
        {
            Accept(b);
        }
    }

    public bool TryTake(out PpiReadResult result) => _ready.TryDequeue(out result);

    /// <summary>Forgets a partial telegram and every untaken result (a new exchange, or a long pause on the line).</summary>
    public void Reset()
    {
        _partial.Clear();
        _ready.Clear();
        _expected = 0;
        _skipped = 0;
    }

    private void Accept(byte b)
    {
        if (_partial.Count == 0)
        {
            Begin(b);
            return;
        }

        _partial.Add(b);
        if (_partial.Count == 4 && _partial[0] == PpiFrameCodec.StartVariable)
        {
            CheckVariableHeader();
        }
        else if (_partial.Count == _expected)
        {
            Complete();
        }
    }

    private void Begin(byte b)
    {
        switch (b)
        {
            case PpiFrameCodec.ShortAcknowledge:
                Emit(PpiFrame.ShortAcknowledge, PpiFrameError.None);
                return;
            case PpiFrameCodec.StartFixed:
                _expected = PpiFrameCodec.FixedLength;
                break;
            case PpiFrameCodec.StartToken:
                _expected = 3;
                break;
            case PpiFrameCodec.StartVariable:
                _expected = 4;
                break;
            default:
                _skipped++;
                return;
        }

        _partial.Add(b);
    }

    private void CheckVariableHeader()
    {
        var length = _partial[1];
        var error = _partial[2] != length || _partial[3] != PpiFrameCodec.StartVariable ? PpiFrameError.BadHeader
            : length is < 4 or > PpiFrameCodec.MaxData + 3 ? PpiFrameError.LengthOutOfRange
            : PpiFrameError.None;
        if (error == PpiFrameError.None)
        {
            _expected = length + 6;
            return;
        }

        // The 16#68 began no telegram: report it, then search the three characters after it again.
        byte[] rest = [_partial[1], _partial[2], _partial[3]];
        _partial.Clear();
        Emit(null, error);
        foreach (var b in rest)
        {
            Accept(b);
        }
    }

    private void Complete()
    {
        var bytes = _partial.ToArray();
        _partial.Clear();
        switch (bytes[0])
        {
            case PpiFrameCodec.StartToken:
                Emit(PpiFrame.Token(bytes[1], bytes[2]), PpiFrameError.None);
                return;
            case PpiFrameCodec.StartFixed:
                Finish(bytes, 1, 3, PpiFrame.Fixed(bytes[1], bytes[2], bytes[3]));
                return;
            default:
                var length = bytes[1];
                var body = bytes.AsSpan(4, length);
                Finish(bytes, 4, length, PpiFrame.Variable(body[0], body[1], body[2], body[3..]));
                return;
        }
    }

    private void Finish(byte[] bytes, int checkedFrom, int checkedCount, PpiFrame frame)
    {
        var error = bytes[^1] != PpiFrameCodec.End ? PpiFrameError.BadEnd
            : bytes[^2] != PpiFrameCodec.Checksum(bytes.AsSpan(checkedFrom, checkedCount)) ? PpiFrameError.ChecksumMismatch
            : PpiFrameError.None;
        Emit(error == PpiFrameError.None ? frame : null, error);
    }

    private void Emit(PpiFrame? frame, PpiFrameError error)
    {
        _ready.Enqueue(new PpiReadResult(frame, error, _skipped));
        _skipped = 0;
        _expected = 0;
    }
}
