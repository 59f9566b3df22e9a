using System.Globalization;

namespace OperatorPanel.Core.Projects;

/// <summary>
/// Reads the project's optional <c>history</c> object; a project without one records with <see cref="HistorySettings.Default"/>,
/// so files written before the historian load unchanged.
/// </summary>
internal static class HistorySettingsReader
{
    public static HistorySettings? Read(JsonFields project)
    {
        if (!project.Has("history"))
        {
            return HistorySettings.Default;
        }

        if (project.Object("history") is not { } fields)
        {
            return null;
        }

        var d = HistorySettings.Default;
        fields.ReportUnknown("enabled", "deadbandPercent", "samplePeriodS", "retentionDays", "maxSizeMb");
        var enabled = fields.Bool("enabled", d.Enabled);
        var deadband = fields.Number("deadbandPercent", d.DeadbandPercent);
        if (deadband is < 0 or > HistorySettings.MaxDeadbandPercent)
        {
            fields.Problem("deadbandPercent", string.Create(CultureInfo.InvariantCulture, $"deadband {deadband} % is outside 0-{HistorySettings.MaxDeadbandPercent} %"));
            deadband = null;
        }

        var sample = Ranged(fields, "samplePeriodS", (int)d.SamplePeriod.TotalSeconds, HistorySettings.MinSamplePeriodS, HistorySettings.MaxSamplePeriodS, "s");
        var days = Ranged(fields, "retentionDays", d.RetentionDays, 1, HistorySettings.MaxRetentionDays, "days");
        var size = Ranged(fields, "maxSizeMb", d.MaxSizeMb, HistorySettings.MinSizeMb, HistorySettings.MaxSizeMbLimit, "MB");
        return enabled is { } e && deadband is { } p && sample is { } s && days is { } r && size is { } m
            ? new HistorySettings(e, p, TimeSpan.FromSeconds(s), r, m)
            : null;
    }

    private static int? Ranged(JsonFields fields, string name, int fallback, int min, int max, string unit)
    {
        var value = fields.Int(name, fallback);
        if (value is { } v && (v < min || v > max))
        {
            fields.Problem(name, string.Create(CultureInfo.InvariantCulture, $"{v} {unit} is outside {min}-{max} {unit}"));
            return null;
        }

        return value;
    }
}
