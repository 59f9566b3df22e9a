using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Values;

namespace OperatorPanel.Historian.Recording;

/// <summary>
/// One value the historian records: an I/O symbol or a tag of the project, by station and address (two tags on one
/// address, say VD120 as a float and in hex, are one recorded value, named and decoded as the first of them).
/// </summary>
/// <param name="Station">The station's bus address.</param>
/// <param name="Address">The value's address; its width and <paramref name="Format"/> decode the stored integer.</param>
/// <param name="Symbol">The project's name for it.</param>
/// <param name="Format">How it is shown; decides whether a deadband applies (numbers) or every change counts (bits, codes).</param>
/// <param name="Deadband">The tag's own deadband in its units; null: the project's percentage.</param>
public sealed record RecordedTag(Station Station, PlcAddress Address, string Symbol, DisplayFormat Format, double? Deadband)
{
    /// <summary>Numbers move by amounts a deadband can judge; a bit, a hex code, a bit pattern or characters change or do not.</summary>
    public bool IsNumeric => Format is DisplayFormat.Unsigned or DisplayFormat.Signed or DisplayFormat.Float;

    /// <summary>The tag's linear scale: histories and trends show the engineering value; the stored integer stays raw.</summary>
    public TagScale? Scale { get; init; }

    /// <summary>The tag's unit, shown after its value ("16.7 %").</summary>
    public string? Unit { get; init; }

    /// <summary>A value as the panel shows it: format, scale and unit ("16.7 %").</summary>
    public string Text(ReadOnlySpan<byte> raw) => TagValues.Format(Address, Format, Scale, Unit, raw);

    /// <summary>Every recorded value of <paramref name="project"/>: inputs, outputs, then the tags not marked "record": false.</summary>
    public static IReadOnlyList<RecordedTag> Of(PanelProject project)
    {
        ArgumentNullException.ThrowIfNull(project);
        var tags = new List<RecordedTag>();
        var seen = new HashSet<(Station, PlcAddress)>();
        foreach (var station in project.Stations)
        {
            var candidates = station.Inputs.Concat(station.Outputs).Select(s => new RecordedTag(station.Address, s.Address, s.Symbol, DisplayFormat.Bool, null))
                .Concat(station.Tags.Where(t => t.Recorded).Select(t => new RecordedTag(station.Address, t.Address, t.Symbol, t.Format, t.Deadband) { Scale = t.Scale, Unit = t.Unit }));
            tags.AddRange(candidates.Where(c => seen.Add((c.Station, c.Address))));
        }

        return tags;
    }
}
