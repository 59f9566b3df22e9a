using System.Text;

namespace OperatorPanel.Core.Alarms;

/// <summary>
/// The alarm history as CSV for a spreadsheet (RFC 4180: comma separated, CRLF after every record, a field quoted when it
/// holds a comma, quote, CR or LF, quotes doubled). Times are ISO 8601 UTC (<see cref="AlarmTime"/>).
/// </summary>
public static class AlarmCsv
{
    public const string Header = "Time,Station,Address,Flag,Event,State,Class,Text";

    public static string Format(IEnumerable<AlarmEvent> history)
    {
        ArgumentNullException.ThrowIfNull(history);
        var csv = new StringBuilder(Header).Append("\r\n");
        foreach (var e in history)
        {
            string[] fields =
            [
                AlarmTime.Format(e.At), e.StationName, e.Station.Address.ToString(System.Globalization.CultureInfo.InvariantCulture),
                e.Flag.ToString(), e.TransitionText, e.StateText, Words(e.Class.ToString()), e.Text,
            ];
            csv.AppendJoin(',', fields.Select(Quote)).Append("\r\n");
        }

        return csv.ToString();
    }

    public static string Quote(string field)
    {
        ArgumentNullException.ThrowIfNull(field);
        return field.AsSpan().IndexOfAny(",\"\r\n") < 0 ? field : "\"" + field.Replace("\"", "\"\"", StringComparison.Ordinal) + "\"";
    }

    /// <summary>"ActiveUnacknowledged" → "active unacknowledged", as the alarm window says it.</summary>
    public static string Words(string pascal)
    {
        ArgumentNullException.ThrowIfNull(pascal);
        var words = new StringBuilder();
        foreach (var c in pascal)
        {
            if (char.IsUpper(c) && words.Length > 0)
            {
                words.Append(' ');
            }

            words.Append(char.ToLowerInvariant(c));
        }

        return words.ToString();
    }
}
