using System.Diagnostics.CodeAnalysis;

namespace OperatorPanel.Core.Values;

/// <summary>
/// The values an operator may write to a memory cell, in its engineering units (after <see cref="TagScale"/>): RecipeNumber
/// 1..8. Either end may be open. Written "1..8", "0.." or "..100".
/// </summary>
public sealed record TagRange(double? Min, double? Max)
{
    public bool Contains(double value) => (Min is not { } min || value >= min) && (Max is not { } max || value <= max);

    public override string ToString() => $"{(Min is { } min ? TagScale.Number(min) : string.Empty)}..{(Max is { } max ? TagScale.Number(max) : string.Empty)}";

    /// <summary>"1..8", "0..", "..100"; empty text is no range (null, true).</summary>
    public static bool TryParse(string? text, out TagRange? range, [NotNullWhen(false)] out string? error)
    {
        range = null;
        error = null;
        if (string.IsNullOrWhiteSpace(text))
        {
            return true;
        }

        var parts = text.Split("..", StringSplitOptions.TrimEntries);
        double? min = null, max = null;
        if (parts.Length != 2 || (parts[0].Length > 0 && !Number(parts[0], out min)) || (parts[1].Length > 0 && !Number(parts[1], out max)) || (min is null && max is null))
        {
            error = $"'{text.Trim()}' is not a range; write it as min..max, e.g. 1..8 (0.. or ..100 for one end)";
            return false;
        }

        if (min > max)
        {
            error = $"the range {text.Trim()} ends below its start";
            return false;
        }

        range = new TagRange(min, max);
        return true;
    }

    private static bool Number(string text, out double? value)
    {
        var ok = TagScale.TryNumber(text, out var number);
        value = ok ? number : null;
        return ok;
    }
}
