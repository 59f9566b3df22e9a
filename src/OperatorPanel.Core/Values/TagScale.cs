using System.Diagnostics.CodeAnalysis;
using System.Globalization;

namespace OperatorPanel.Core.Values;

/// <summary>
/// Linear scaling of a memory cell, as an HMI has it: the PLC's raw number <see cref="RawLow"/>..<see cref="RawHigh"/>
/// is the engineering value <see cref="Low"/>..<see cref="High"/> (TankLevel: raw 0..1000 is 0..100 %, so 552 shows
/// as 55.2). Written "0..1000 -> 0..100" in the wizard and in messages.
/// </summary>
public sealed record TagScale(double RawLow, double RawHigh, double Low, double High)
{
    public double ToValue(double raw) => Low + ((raw - RawLow) * (High - Low) / (RawHigh - RawLow));

    public double ToRaw(double value) => RawLow + ((value - Low) * (RawHigh - RawLow) / (High - Low));

    /// <summary>Digits after the point that show one raw step (0.1 per step: 1 digit); at most 6.</summary>
    public int Decimals
    {
        get
        {
            var step = Math.Abs((High - Low) / (RawHigh - RawLow));
            return step >= 1 ? 0 : Math.Min(6, (int)Math.Ceiling(-Math.Log10(step) - 1e-9));
        }
    }

    /// <summary>Why these four numbers are no scale; null when they are one.</summary>
    public string? Problem() =>
        !double.IsFinite(RawLow) || !double.IsFinite(RawHigh) || !double.IsFinite(Low) || !double.IsFinite(High) ? "every number of a scale must be finite"
        : RawLow == RawHigh ? "rawLow and rawHigh are equal: no raw span to scale"
        : Low == High ? "low and high are equal: every raw value would show the same"
        : null;

    public override string ToString() => $"{Number(RawLow)}..{Number(RawHigh)} -> {Number(Low)}..{Number(High)}";

    /// <summary>"0..1000 -> 0..100"; empty text is no scale (null, true).</summary>
    public static bool TryParse(string? text, out TagScale? scale, [NotNullWhen(false)] out string? error)
    {
        scale = null;
        error = null;
        if (string.IsNullOrWhiteSpace(text))
        {
            return true;
        }

        var sides = text.Split("->", StringSplitOptions.TrimEntries);
        if (sides.Length != 2 || !TryPair(sides[0], out var raw) || !TryPair(sides[1], out var value))
        {
            error = $"'{text.Trim()}' is not a scale; write it as raw low..high -> value low..high, e.g. 0..1000 -> 0..100";
            return false;
        }

        scale = new TagScale(raw.Low, raw.High, value.Low, value.High);
        error = scale.Problem();
        scale = error is null ? scale : null;
        return error is null;
    }

    public static string Number(double value) => value.ToString("0.######", CultureInfo.InvariantCulture);

    private static bool TryPair(string text, out (double Low, double High) pair)
    {
        pair = default;
        var parts = text.Split("..", StringSplitOptions.TrimEntries);
        return parts.Length == 2 && TryNumber(parts[0], out pair.Low) && TryNumber(parts[1], out pair.High);
    }

    internal static bool TryNumber(string text, out double value) =>
        double.TryParse(text, NumberStyles.Float, CultureInfo.InvariantCulture, out value) && double.IsFinite(value);
}
