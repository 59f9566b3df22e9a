using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Projects;

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
    public double? Number(HistorySample sample) => sample.Stored is { } v ? TagValue.ToNumber(v, Address, Format) : null;

    public string Text(HistorySample sample) => sample.Stored is { } v ? TagValue.ToText(v, Address, Format) : "-";
}
