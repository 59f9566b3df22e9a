using OperatorPanel.Simulator.Hosting;
using OperatorPanel.Simulator.Reference;

namespace OperatorPanel.Simulator.Soak;

/// <summary>
/// The soak judge's view into the simulated PLC: wraps a line, runs it in steps of <see cref="StlLine.Slice"/> and
/// after every step (and every delivery, where the reference model acts) compares the <see cref="WatchedBytes"/> with
/// the copy it kept, recording each difference as a <see cref="MemoryChange"/>, in order. A step is shorter than any
/// frame, and the handler stores a WRITE's data with one instruction (BMB) and a WRITE BITS byte with one (XORB), so one
/// change of Q, M or V is one executed write. A change of I or SM is the field's (<see cref="SoakField"/>), which
/// the judge holds against what the field set. A write that stores what is already there changes nothing and is not
/// seen: words and double words are never written twice with one value, bytes and bits can be (the judge says so).
/// </summary>
public sealed class ExecutedWriteObserver : ISimulatedLine
{
    private readonly ISimulatedLine _inner;
    private readonly PlcMemory _memory;
    private readonly IReadOnlyList<(WatchedBytes Range, byte[] Copy)> _watched;
    private readonly TimeProvider _time;
    private readonly List<MemoryChange> _changes = [];
    private readonly Lock _lock = new();
    private readonly MemoryImage _initial;

    public ExecutedWriteObserver(ISimulatedLine inner, PlcMemory memory, IEnumerable<WatchedBytes> watched, TimeProvider time)
    {
        ArgumentNullException.ThrowIfNull(inner);
        ArgumentNullException.ThrowIfNull(memory);
        ArgumentNullException.ThrowIfNull(watched);
        ArgumentNullException.ThrowIfNull(time);
        (_inner, _memory, _time) = (inner, memory, time);
        _watched = [.. watched.Select(w => (w, memory.Area(w.Area).AsSpan(w.First, w.Count).ToArray()))];
        _initial = new MemoryImage(_watched);
    }

    /// <summary>The watched bytes as they were when the observer started: the judge's starting point.</summary>
    public MemoryImage Initial => _initial.Copy();

    public TimeSpan Now => _inner.Now;

    public int FramesReceived => _inner.FramesReceived;

    public int Replies => _inner.Replies;

    public TimeSpan? NextOutput => _inner.NextOutput;

    /// <summary>The changes seen so far, oldest first.</summary>
    public IReadOnlyList<MemoryChange> Changes
    {
        get { lock (_lock) { return [.. _changes]; } }
    }

    public void RunUntil(TimeSpan until)
    {
        while (_inner.Now < until)
        {
            var step = _inner.Now + StlLine.Slice < until ? _inner.Now + StlLine.Slice : until;
            _inner.RunUntil(step);
            Look();
        }
    }

    public void Deliver(ReadOnlySpan<byte> characters)
    {
        _inner.Deliver(characters);
        Look();
    }

    public byte[] TakeTransmitted() => _inner.TakeTransmitted();

    private void Look()
    {
        foreach (var (range, copy) in _watched)
        {
            var now = _memory.Area(range.Area).AsSpan(range.First, range.Count);
            var first = FirstDifference(now, copy);
            if (first < 0)
            {
                continue;
            }

            var last = LastDifference(now, copy);
            var change = new MemoryChange(
                _time.GetTimestamp(), range.Area, range.First + first,
                [.. copy.AsSpan(first, last - first + 1)], [.. now.Slice(first, last - first + 1)]);
            now.CopyTo(copy);
            lock (_lock) { _changes.Add(change); }
        }
    }

    private static int FirstDifference(ReadOnlySpan<byte> now, ReadOnlySpan<byte> copy)
    {
        var common = now.CommonPrefixLength(copy);
        return common == now.Length ? -1 : common;
    }

    private static int LastDifference(ReadOnlySpan<byte> now, ReadOnlySpan<byte> copy)
    {
        var last = now.Length - 1;
        while (now[last] == copy[last])
        {
            last--;
        }

        return last;
    }
}
