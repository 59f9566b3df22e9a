using System.Diagnostics.CodeAnalysis;
using System.Globalization;

namespace OperatorPanel.Simulator.Soak;

/// <summary>
/// The faults a noisy line puts on every character, each direction on its own: a data bit flipped (rate per bit), a
/// character lost (rate per character), a whole frame lost from its '&lt;' to its '&gt;' (rate per frame).
/// </summary>
public sealed record LineFaults(string Name, double BitFlipRate, double CharacterDropRate, double FrameDropRate)
{
    /// <summary>1% of data bits flipped: the XOR check of protocol v1 lets some of these through.</summary>
    public static LineFaults Flips { get; } = new("flips", 0.01, 0, 0);

    /// <summary>0.5% flips, 0.5% dropped characters, 5% dropped frames: lost replies, cut frames, retries.</summary>
    public static LineFaults Mixed { get; } = new("mixed", 0.005, 0.005, 0.05);

    /// <summary>No faults: the baseline, what the rig itself costs.</summary>
    public static LineFaults Clean { get; } = new("clean", 0, 0, 0);

    public static IReadOnlyList<LineFaults> Profiles { get; } = [Flips, Mixed, Clean];

    /// <summary>A profile by name (flips, mixed, clean); false with the names that exist.</summary>
    public static bool TryFind(string name, [NotNullWhen(true)] out LineFaults? faults, [NotNullWhen(false)] out string? error)
    {
        faults = Profiles.FirstOrDefault(p => string.Equals(p.Name, name, StringComparison.OrdinalIgnoreCase));
        error = faults is null ? $"no fault profile '{name}': use {string.Join(" or ", Profiles.Select(p => p.Name))}" : null;
        return faults is not null;
    }

    public override string ToString() => string.Create(
        CultureInfo.InvariantCulture,
        $"{Name}: {BitFlipRate:P1} bits flipped, {CharacterDropRate:P1} characters dropped, {FrameDropRate:P0} frames dropped");
}
