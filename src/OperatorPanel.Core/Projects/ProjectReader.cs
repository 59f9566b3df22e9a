using System.Globalization;
using System.Text.Json;
using OperatorPanel.Core.Polling;

namespace OperatorPanel.Core.Projects;

/// <summary>Turns a parsed project document into a <see cref="PanelProject"/>, collecting every problem on the way.</summary>
internal static class ProjectReader
{
    public static PanelProject? Read(JsonElement root, ProjectProblems problems)
    {
        var fields = JsonFields.Open(root, JsonPath.Root, problems);
        var version = fields?.Int("schemaVersion");
        if (fields is null || version is null)
        {
            return null;
        }

        if (version != ProjectFile.SchemaVersion)
        {
            // A file from another schema would produce a flood of follow-on problems; the version is the one to fix.
            fields.Problem("schemaVersion", version > ProjectFile.SchemaVersion
                ? $"schema version {version} is newer than this program reads ({ProjectFile.SchemaVersion}); update Operator Panel"
                : $"unknown schema version {version}; this program reads version {ProjectFile.SchemaVersion}");
            return null;
        }

        fields.ReportUnknown("schemaVersion", "name", "refresh", "history", "alarmSound", "stations");
        var name = TextRule.ProjectName.Read(fields, "name", fallback: string.Empty);
        var refresh = ReadRefresh(fields.Object("refresh"));
        var history = HistorySettingsReader.Read(fields);
        var alarmSound = fields.Bool("alarmSound", fallback: true);
        var stations = StationReader.ReadAll(fields, problems);
        return problems.Count == 0 && name is not null && refresh is not null && history is not null && alarmSound is { } sound && stations is { } list
            ? new PanelProject(name, refresh, list) { History = history, AlarmSound = sound }
            : null;
    }

    private static RefreshSettings? ReadRefresh(JsonFields? fields)
    {
        if (fields is null)
        {
            return null;
        }

        fields.ReportUnknown("mode", "minimumPeriodMs");
        var modeText = fields.String("mode");
        RefreshMode? mode = null;
        if (modeText is not null && RefreshModeWords.TryParse(modeText, out var parsed))
        {
            mode = parsed;
        }
        else if (modeText is not null)
        {
            fields.Problem("mode", $"unknown refresh mode '{JsonPath.Shorten(modeText)}'; use {RefreshModeWords.Continuous} or {RefreshModeWords.Triggered}");
        }

        var defaultMs = (int)RefreshSettings.Default.MinimumPeriod.TotalMilliseconds;
        var maxMs = (int)RefreshSettings.MaxMinimumPeriod.TotalMilliseconds;
        var periodMs = fields.Int("minimumPeriodMs", defaultMs);
        if (periodMs is < 0 || periodMs > maxMs)
        {
            fields.Problem("minimumPeriodMs", string.Create(CultureInfo.InvariantCulture, $"minimum period {periodMs} ms is outside 0-{maxMs} ms"));
            periodMs = null;
        }

        return mode is { } m && periodMs is { } ms ? new RefreshSettings(m, TimeSpan.FromMilliseconds(ms)) : null;
    }
}
