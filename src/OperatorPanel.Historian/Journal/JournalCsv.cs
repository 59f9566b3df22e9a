using System.Globalization;
using System.Text;
using OperatorPanel.Core.Alarms;

namespace OperatorPanel.Historian.Journal;

/// <summary>
/// Alarm journal entries as CSV for a spreadsheet, in the alarm history's form (<see cref="AlarmCsv"/>: RFC 4180, ISO 8601
/// UTC times) with who acknowledged in a last column.
/// </summary>
public static class JournalCsv
{
    public const string Header = AlarmCsv.Header + ",User";

    public static string Format(IEnumerable<JournalEntry> entries)
    {
        ArgumentNullException.ThrowIfNull(entries);
        var csv = new StringBuilder(Header).Append("\r\n");
        foreach (var (e, user) in entries.Select(x => (x.Event, x.User)))
        {
            string[] fields =
            [
                AlarmTime.Format(e.At), e.StationName, e.Station.Address.ToString(CultureInfo.InvariantCulture), e.Flag.ToString(),
                e.TransitionText, e.StateText, AlarmCsv.Words(e.Class.ToString()), e.Text, user ?? string.Empty,
            ];
            csv.AppendJoin(',', fields.Select(AlarmCsv.Quote)).Append("\r\n");
        }

        return csv.ToString();
    }
}
