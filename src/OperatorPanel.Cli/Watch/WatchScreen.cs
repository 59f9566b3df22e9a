using Spectre.Console;
using Spectre.Console.Rendering;

namespace OperatorPanel.Cli.Watch;

/// <summary>
/// watch's view on a terminal of any size: fitted to its height by giving way in <see cref="ViewLine.Priority"/> order
/// (lamp symbols, then lamps, then tags, then link counters; the title, each station's state and error and its alarms
/// always stay), with one line saying what gave way; and each line cut at the width with an ellipsis, never wrapped.
/// Spectre.Console draws it in place (LiveOutput).
/// </summary>
internal static class WatchScreen
{
    public static IRenderable Render(WatchSnapshot snapshot, int width, int height) =>
        new Rows(Fit(SnapshotRenderer.Lines(snapshot), height).Select(l => Line(l, width)));

    /// <summary>
    /// The lines that fit <paramref name="height"/> rows: lower-priority lines leave first, the last station's first
    /// within one priority, and a note counts them. Lines that are always kept are cut from the bottom only when they
    /// alone are too many.
    /// </summary>
    public static List<ViewLine> Fit(List<ViewLine> lines, int height)
    {
        height = Math.Max(height, 2);
        if (lines.Count <= height)
        {
            return lines;
        }

        var shown = new List<ViewLine>(lines);
        var hidden = 0;
        for (var priority = lines.Max(l => l.Priority); priority > ViewLine.Keep && shown.Count + 1 > height; priority--)
        {
            for (var i = shown.Count - 1; i >= 0 && shown.Count + 1 > height; i--)
            {
                if (shown[i].Priority == priority)
                {
                    shown.RemoveAt(i);
                    hidden++;
                }
            }
        }

        if (shown.Count + 1 > height)
        {
            hidden += shown.Count - (height - 1);
            shown.RemoveRange(height - 1, shown.Count - (height - 1));
        }

        shown.Add(new ViewLine($"({hidden} lines hidden: a taller window or --json shows all)", ViewLine.Keep));
        return shown;
    }

    private static Text Line(ViewLine line, int width) =>
        new(Cut(line.Text, width), line.Kind switch
        {
            ViewLineKind.Title => new Style(decoration: Decoration.Bold),
            ViewLineKind.Station => new Style(decoration: Decoration.Bold),
            ViewLineKind.Problem => new Style(Color.Yellow),
            ViewLineKind.Alarm => new Style(Color.Red),
            ViewLineKind.Unknown => new Style(Color.Yellow),
            ViewLineKind.Plain => Style.Plain,
        })
        {
            Overflow = Overflow.Ellipsis,
        };

    /// <summary>Cut here too: the width the view is fitted for is the one it is drawn at, whatever Spectre's own guess.</summary>
    private static string Cut(string text, int width) =>
        width > 1 && text.Length > width ? text[..(width - 1)] + "…" : text;
}
