using System.Globalization;
using OperatorPanel.Core.Alarms;
using OperatorPanel.Historian.Reading;

namespace OperatorPanel.Cli.History;

/// <summary><c>opanel history</c>'s output: a table in local time, CSV in UTC, or one JSON document.</summary>
internal sealed record HistoryView(
    string Project, string Database, bool Exists, DateTimeOffset From, DateTimeOffset To, IReadOnlyList<NamedTag> Tags, IReadOnlyList<TagHistory> Histories)
{
    public void Print(CliContext cli, bool csv)
    {
        var rows = Rows().ToList();
        if (cli.Json)
        {
            cli.WriteJson(new
            {
                ok = true,
                project = Project,
                database = Database,
                from = From,
                to = To,
                tags = Tags.Zip(Histories, (tag, history) => new
                {
                    station = tag.StationName,
                    symbol = tag.Tag.Symbol,
                    address = tag.Tag.Address.ToString(),
                    format = tag.Tag.Format,
                    samples = history.Samples.Select(s => new { time = s.At, value = s.Stored is null ? null : history.Text(s), number = history.Number(s), quality = Quality(s) }),
                }),
            });
            return;
        }

        if (csv)
        {
            cli.Out.Write("Time,Station,Symbol,Address,Value,Number,Quality\r\n");
            foreach (var (tag, history, sample) in rows)
            {
                string[] fields =
                [
                    AlarmTime.Format(sample.At), tag.StationName, tag.Tag.Symbol, tag.Tag.Address.ToString(), sample.Stored is null ? string.Empty : history.Text(sample),
                    history.Number(sample)?.ToString("R", CultureInfo.InvariantCulture) ?? string.Empty, Quality(sample),
                ];
                cli.Out.Write(string.Join(',', fields.Select(AlarmCsv.Quote)) + "\r\n");
            }

            return;
        }

        var local = TimeZoneInfo.Local;
        cli.Out.WriteLine($"{Project}: history from {Local(From, local)} to {Local(To, local)} (local time), {rows.Count} rows");
        if (!Exists)
        {
            cli.Out.WriteLine($"nothing recorded yet: {Database} does not exist (opanel watch, opanel trend and the panel record it)");
            return;
        }

        var width = Math.Max(8, Tags.Select(t => t.Name.Length).DefaultIfEmpty(0).Max());
        foreach (var (tag, history, sample) in rows)
        {
            cli.Out.WriteLine($"{Local(sample.At, local)}  {tag.Name.PadRight(width)}  {(sample.Stored is null ? "-" : history.Text(sample)),12}  {Quality(sample)}");
        }
    }

    private IEnumerable<(NamedTag Tag, TagHistory History, HistorySample Sample)> Rows() =>
        Tags.Zip(Histories).SelectMany(p => p.Second.Samples.Select(s => (p.First, p.Second, s))).OrderBy(r => r.s.At);

    private static string Quality(HistorySample sample) => sample.Quality.ToString().ToLowerInvariant();

    private static string Local(DateTimeOffset at, TimeZoneInfo zone) =>
        TimeZoneInfo.ConvertTime(at, zone).ToString("yyyy-MM-dd HH:mm:ss.fff", CultureInfo.InvariantCulture);
}
