namespace OperatorPanel.Core.Link;

/// <summary>
/// How a <see cref="PlcLink"/> gets its port back after the device vanished (USB adapter pulled, radio module reset).
/// Kept apart from <see cref="LinkOptions"/>, which are the timing rules of the protocol on the wire.
/// </summary>
public sealed record ReconnectOptions
{
    public static readonly ReconnectOptions Default = new();

    /// <summary>
    /// Shortest time between two attempts to open a port that could not be opened: a returning device is found within
    /// this, and a missing one costs one failed open per interval instead of a busy loop.
    /// </summary>
    public TimeSpan ReopenInterval { get; init; } = TimeSpan.FromMilliseconds(500);
}
