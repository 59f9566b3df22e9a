using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Values;

namespace OperatorPanel.Historian.Reading;

/// <summary>
/// One value's rows over a time range, oldest first. The first row may be before the range's start: it is the value the
/// range starts with (each row holds until the next one, within a <see cref="RecordingSpan"/>).
/// </summary>
/// <param name="Station">The station.</param>
/// <param name="Address">The value's address.</param>
/// <param name="Symbol">The name it was recorded under.</param>
/// <param name="Format">How it was shown, which decodes <see cref="HistorySample.Stored"/> (<see cref="TagValue"/>).</param>
/// <param name="Samples">The rows.</param>
public sealed record TagHistory(Station Station, PlcAddress Address, string Symbol, DisplayFormat Format, IReadOnlyList<HistorySample> Samples)
{
    /// <summary>The tag's scale as the project has it now: numbers and texts in engineering units (HistoryReader.Read with the recorded tags).</summary>
    public TagScale? Scale { get; init; }

    /// <summary>The tag's unit, shown after each value.</summary>
    public string? Unit { get; init; }

    /// <summary>The number a trend plots: the value in the tag's format, scaled; null for a row without a value.</summary>
    public double? Number(HistorySample sample) => sample.Stored is { } v
        ? TagValue.ToNumber(v, Address, Format) is var number && Scale is { } scale && TagValues.IsNumeric(Format) ? scale.ToValue(number) : number
        : null;

    /// <summary>The value as the panel shows it ("16.7 %"); "-" for a row without a value.</summary>
    public string Text(HistorySample sample) => sample.Stored is { } v
        ? Format.Fits(Address.Width) ? TagValues.Format(Address, Format, Scale, Unit, TagValue.ToRaw(v, Address).AsSpan()) : TagValue.ToText(v, Address, Format)
        : "-";
}
