using System.Collections.Immutable;

namespace OperatorPanel.Core.Polling;

/// <summary>
/// The panel's latest knowledge of one address. <see cref="Raw"/> holds the address's bytes big-endian, as the
/// S7-200 stores them (VW100 = VB100 high, VB101 low); a bit address holds one byte, 00 or 01. Empty when never read.
/// <see cref="Timestamp"/> is when <see cref="Raw"/> was read (kept while stale); for a bad value, when it was last tried.
/// </summary>
public sealed record PolledValue(ImmutableArray<byte> Raw, DateTimeOffset Timestamp, ValueQuality Quality, string? Error)
{
    public bool HasValue => !Raw.IsDefaultOrEmpty;

    /// <summary>For a bit address: the bit; null when never read.</summary>
    public bool? AsBit => HasValue ? Raw[0] != 0 : null;

    public static PolledValue NotRead(DateTimeOffset at) => new([], at, ValueQuality.Bad, "not read yet");

    public static PolledValue Good(ImmutableArray<byte> raw, DateTimeOffset at) => new(raw, at, ValueQuality.Good, null);

    /// <summary>True when a subscriber must hear about the step from this value to <paramref name="next"/>.</summary>
    public bool DiffersFrom(PolledValue next)
    {
        ArgumentNullException.ThrowIfNull(next);
        return Quality != next.Quality || !Raw.AsSpan().SequenceEqual(next.Raw.AsSpan());
    }
}
