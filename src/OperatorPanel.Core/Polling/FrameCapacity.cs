using OperatorPanel.Core.Protocol;

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
        var maxData = new List<int> { 0 };
        for (var items = 1; fits(items, items); items++)
        {
            maxData.Add(MostData(items, fits));
        }

        _maxData = [.. maxData];
        MaxItems = _maxData.Length - 1;
        MaxBlockLength = MaxItems > 0 ? _maxData[1] : 0;
    }

    public int TailBytes { get; }

    /// <summary>Most items one frame may carry (one byte each).</summary>
    public int MaxItems { get; }

    /// <summary>Longest block one frame may carry: ranges longer than this are split.</summary>
    public int MaxBlockLength { get; }

    /// <summary>False when not even a one-byte READ fits: a tail that large is never planned.</summary>
    public bool Usable => MaxItems > 0;

    public int Units => (UnitsPerByte * MaxBlockLength) + UnitsPerItem;

    /// <summary>Whether one frame may carry <paramref name="items"/> blocks of <paramref name="dataBytes"/> bytes in all.</summary>
    public bool Fits(int items, int dataBytes) => items >= 1 && items <= MaxItems && dataBytes <= _maxData[items];

    /// <summary>The largest D with fits(items, D), by bisection (the rules are monotone in D); at least <paramref name="items"/>.</summary>
    private static int MostData(int items, Func<int, int, bool> fits)
    {
        int low = items, high = ProtocolLimits.MaxFrameChars;
        while (low < high)
        {
            var mid = (low + high + 1) / 2;
            if (fits(items, mid))
            {
                low = mid;
            }
            else
            {
                high = mid - 1;
            }
        }

        return low;
    }
}
