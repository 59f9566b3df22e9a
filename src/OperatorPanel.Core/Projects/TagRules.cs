using OperatorPanel.Core.Values;

namespace OperatorPanel.Core.Projects;

/// <summary>
/// Whether a tag's unit, scale and range fit its address and format: the one check behind the project file
/// (TagReader) and the wizard. Scale and range are for numbers; the scale's raw ends and the range's ends must be
/// values the address holds in its format; a unit is a short word.
/// </summary>
public static class TagRules
{
    /// <summary>A unit is a short word shown after the value ("%", "bottles/min").</summary>
    public const int MaxUnitChars = 16;

    /// <summary>The unit's control characters; its length has the message above, which also says what a unit looks like.</summary>
    private static readonly TextRule UnitText = new("the unit", MaxUnitChars, "it is a short word shown after the value");

    /// <summary>The first problem and the file property it belongs to ("unit", "scale", "min", "max"); null when the tag is fine.</summary>
    public static (string Property, string Message)? Problem(ProjectTag tag)
    {
        ArgumentNullException.ThrowIfNull(tag);
        if (tag.Unit is { } unit && (unit.Trim().Length == 0 || unit.Length > MaxUnitChars || unit != unit.Trim()))
        {
            return ("unit", $"a unit is 1-{MaxUnitChars} characters without spaces around (\"%\", \"ml\", \"bottles/min\"); leave it out for none");
        }

        if (tag.Unit is { } shown && UnitText.Problem(shown) is { } hidden)
        {
            return ("unit", hidden);
        }

        if ((tag.Scale is not null || tag.Range is not null) && !TagValues.IsNumeric(tag.Format))
        {
            return (tag.Scale is not null ? "scale" : tag.Range!.Min is not null ? "min" : "max",
                $"scale, min and max are for numbers: the format of {tag.Address} is {JsonWords.Of(tag.Format)}; use unsigned, signed or float");
        }

        if (tag.Scale is { } scale)
        {
            if (scale.Problem() is { } problem)
            {
                return ("scale", problem);
            }

            foreach (var (raw, name) in new[] { (scale.RawLow, "rawLow"), (scale.RawHigh, "rawHigh") })
            {
                if (!ValueParser.TryParse(TagScale.Number(raw), tag.Address, tag.Format, out _, out var error))
                {
                    return ("scale", $"{name} {TagScale.Number(raw)}: {error.Message}");
                }
            }
        }

        if (tag.Range is { Min: { } min, Max: { } max } && min > max)
        {
            return ("max", $"max {TagScale.Number(max)} is below min {TagScale.Number(min)}");
        }

        foreach (var (end, name) in new[] { (tag.Range?.Min, "min"), (tag.Range?.Max, "max") })
        {
            if (end is { } value && !TagValues.TryParse(tag with { Range = null }, TagScale.Number(value), out _, out var error))
            {
                return (name, error.Message);
            }
        }

        return null;
    }
}
