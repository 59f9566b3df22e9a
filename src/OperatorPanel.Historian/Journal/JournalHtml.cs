using System.Globalization;
using System.Net;
using System.Text;
using OperatorPanel.Core.Alarms;

namespace OperatorPanel.Historian.Journal;

/// <summary>
/// Alarm journal entries as one self-contained HTML page to print from the browser (A4, a header on every page, the
/// filter that chose them, times in the panel's local zone): no PDF library needed, and the page reads the same on screen.
/// </summary>
public static class JournalHtml
{
    public static string Format(string title, string selection, DateTimeOffset printedAt, TimeZoneInfo zone, IEnumerable<JournalEntry> entries)
    {
        ArgumentNullException.ThrowIfNull(entries);
        ArgumentNullException.ThrowIfNull(zone);
        var html = new StringBuilder();
        html.Append("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>").Append(E(title)).Append("</title>\n<style>\n")
            .Append("body{font-family:Arial,Helvetica,sans-serif;font-size:10pt;margin:16px}h1{font-size:14pt;margin:0 0 4px}p{margin:2px 0 8px;color:#444}\n")
            .Append("table{border-collapse:collapse;width:100%}th,td{border:1px solid #999;padding:2px 4px;text-align:left;vertical-align:top}\n")
            .Append("thead{display:table-header-group}tr{page-break-inside:avoid}.fault td{background:#fde0e0}.warning td{background:#fff2cc}\n")
            .Append("@page{size:A4 landscape;margin:12mm}@media print{button{display:none}}\n</style></head><body>\n")
            .Append("<button onclick=\"window.print()\">Print</button>\n<h1>").Append(E(title)).Append("</h1>\n<p>")
            .Append(E(selection)).Append(". Printed ").Append(E(Local(printedAt, zone))).Append(", times in ").Append(E(zone.DisplayName)).Append(".</p>\n")
            .Append("<table><thead><tr><th>Time</th><th>Event</th><th>Station</th><th>Flag</th><th>Class</th><th>Text</th><th>State after</th><th>By</th></tr></thead>\n<tbody>\n");
        var count = 0;
        foreach (var (e, user) in entries.Select(x => (x.Event, x.User)))
        {
            count++;
            html.Append("<tr class=\"").Append(e.Class.ToString().ToLowerInvariant()).Append("\"><td>").Append(E(Local(e.At, zone))).Append("</td><td>")
                .Append(E(e.TransitionText)).Append("</td><td>").Append(E(e.StationName)).Append("</td><td>").Append(E(e.Flag.ToString())).Append("</td><td>")
                .Append(E(AlarmCsv.Words(e.Class.ToString()))).Append("</td><td>").Append(E(e.Text)).Append("</td><td>").Append(E(e.StateText))
                .Append("</td><td>").Append(E(user ?? string.Empty)).Append("</td></tr>\n");
        }

        html.Append("</tbody></table>\n<p>").Append(count.ToString(CultureInfo.InvariantCulture)).Append(count == 1 ? " entry" : " entries").Append(".</p>\n</body></html>\n");
        return html.ToString();
    }

    private static string E(string text) => WebUtility.HtmlEncode(text);

    private static string Local(DateTimeOffset at, TimeZoneInfo zone) =>
        TimeZoneInfo.ConvertTime(at, zone).ToString("yyyy-MM-dd HH:mm:ss", CultureInfo.InvariantCulture);
}
