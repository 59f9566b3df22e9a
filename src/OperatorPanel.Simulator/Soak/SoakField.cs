using System.Collections.Immutable;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Simulator.Hosting;
using OperatorPanel.Simulator.Reference;

namespace OperatorPanel.Simulator.Soak;

/// <summary>
/// The field around the soak's PLC: nothing but panel writes changes Q, M and V, and without this nothing would
/// change I or the last SM bytes, so a READ LIST would never carry a change of them. Every <see cref="Period"/> of
/// simulated time it sets its ranges from a pattern fixed by the step number: I bytes in the CPU's physical inputs
/// (<c>inputs</c>: what the STL CPU copies into I at its next scan, or the reference model's I itself), as sensors
/// wired there would; SM bytes in SM, as an intelligent module's status would change (the CPU itself writes no SM byte
/// near the end of the area). Each setting is recorded, in order, as a <see cref="MemoryChange"/> with the time it was
/// made; the judge explains a change of I or SM the observer saw only by the latest setting before it.
/// </summary>
public sealed class SoakField : ISimulatedLine
{
    /// <summary>Long against a refresh (a few per second), so that most READ LISTs still find nothing changed.</summary>
    public static readonly TimeSpan Period = TimeSpan.FromSeconds(1);

    private readonly ISimulatedLine _inner;
    private readonly byte[] _inputs;
    private readonly PlcMemory _memory;
    private readonly ImmutableArray<WatchedBytes> _driven;
    private readonly TimeProvider _time;
    private readonly List<MemoryChange> _settings = [];
    private readonly Lock _lock = new();
    private TimeSpan _due;
    private int _step;

    public SoakField(ISimulatedLine inner, byte[] inputs, PlcMemory memory, IEnumerable<WatchedBytes> driven, TimeProvider time)
    {
        ArgumentNullException.ThrowIfNull(inner);
        ArgumentNullException.ThrowIfNull(inputs);
        ArgumentNullException.ThrowIfNull(memory);
        ArgumentNullException.ThrowIfNull(driven);
        ArgumentNullException.ThrowIfNull(time);
        (_inner, _inputs, _memory, _time) = (inner, inputs, memory, time);
        _driven = [.. driven];
        var other = _driven.Where(r => r.Area is not (ProtocolArea.I or ProtocolArea.SM)).ToList();
        if (other.Count > 0)
        {
            throw new ArgumentException($"{other[0]}: the field sets only I and SM; panel writes alone change Q, M and V", nameof(driven));
        }

        _due = inner.Now + Period;
    }

    public TimeSpan Now => _inner.Now;

    public int FramesReceived => _inner.FramesReceived;

    public int Replies => _inner.Replies;

    public TimeSpan? NextOutput => _inner.NextOutput;

    /// <summary>What the field set, oldest first: <see cref="MemoryChange.After"/> the bytes of one step.</summary>
    public IReadOnlyList<MemoryChange> Settings
    {
        get { lock (_lock) { return [.. _settings]; } }
    }

    /// <summary>The byte the field sets at <paramref name="offset"/> in step <paramref name="step"/>: a hash, so neighbours and steps differ.</summary>
    public static byte Pattern(int step, int offset) => (byte)(unchecked((uint)((step * 1021) + offset + 1) * 2654435761u) >> 24);

    public void RunUntil(TimeSpan until)
    {
        while (_due <= until)
        {
            _inner.RunUntil(_due);
            Set();
            _due += Period;
        }

        _inner.RunUntil(until);
    }

    public void Deliver(ReadOnlySpan<byte> characters) => _inner.Deliver(characters);

    public byte[] TakeTransmitted() => _inner.TakeTransmitted();

    private void Set()
    {
        _step++;
        foreach (var range in _driven)
        {
            var bytes = (range.Area == ProtocolArea.I ? _inputs : _memory.SM).AsSpan(range.First, range.Count);
            var before = bytes.ToArray();
            for (var i = 0; i < bytes.Length; i++)
            {
                bytes[i] = Pattern(_step, range.First + i);
            }

            lock (_lock) { _settings.Add(new MemoryChange(_time.GetTimestamp(), range.Area, range.First, [.. before], [.. bytes])); }
        }
    }
}
