namespace OperatorPanel.Core.Polling;

/// <summary>
/// What one plain READ may carry while the station's buffer tail holds <see cref="TailBytes"/> bytes of stored list
/// descriptors: the exact rule, tabulated per item count (<see cref="Fits"/>) for packing, and its linear form
/// 2D + 4N &lt;= <see cref="Units"/> for the planner's estimates.
/// </summary>
internal sealed class FrameCapacity
{
    /// <summary>Every data byte takes two reply characters of the buffer, every item four bytes of converted descriptors.</summary>
    public const int UnitsPerByte = 2;

    public const int UnitsPerItem = 4;

    /// <summary>Most data bytes per item count (index 0 unused); the rules only get stricter with more items or bytes.</summary>
    private readonly int[] _maxData;

    public FrameCapacity(int tailBytes, Func<int, int, bool> fits)
    {
        TailBytes = tailBytes;
        _maxData = [0, .. Enumerable.Range(1, ProtocolLimitsScan).Select(n => Enumerable.Range(n, ProtocolLimitsScan).TakeWhile(d => fits(n, d)).LastOrDefault()).TakeWhile(d => d > 0)];
        MaxItems = _maxData.Length - 1;
        MaxBlockLength = MaxItems > 0 ? _maxData[1] : 0;
    }

    public int TailBytes { get; }

    /// <summary>Most items one frame may carry (one byte each).</summary>
    public int MaxItems { get; }

    /// <summary>Longest block one frame may carry: ranges longer than this are split.</summary>
    public int MaxBlockLength { get; }

    public int Units => (UnitsPerByte * MaxBlockLength) + UnitsPerItem;

    /// <summary>Whether one frame may carry <paramref name="items"/> blocks of <paramref name="dataBytes"/> bytes in all.</summary>
    public bool Fits(int items, int dataBytes) => items >= 1 && items <= MaxItems && dataBytes <= _maxData[items];

    /// <summary>Item counts and data lengths tried when tabulating: more than any frame of 255 characters can hold.</summary>
    private const int ProtocolLimitsScan = 255;
}
