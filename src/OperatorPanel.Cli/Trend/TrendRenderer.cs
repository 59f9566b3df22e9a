using System.Globalization;
using Spectre.Console;
using Spectre.Console.Rendering;

namespace OperatorPanel.Cli.Trend;

/// <summary>
/// A frame as Spectre.Console renders it: first a line per station that is not online (its state and last error, as watch
/// shows them), then a panel per tag with its value now, the chart rows and the window's range and times under it, or
/// that the window holds no good value. Colour only where the console has it; the characters are the same either way.
/// </summary>
internal static class TrendRenderer
{
    public static IRenderable Render(TrendFrame frame)
    {
        ArgumentNullException.ThrowIfNull(frame);
        var local = TimeZoneInfo.Local;
        var from = TimeZoneInfo.ConvertTime(frame.From, local).ToString("HH:mm:ss", CultureInfo.InvariantCulture);
        var to = TimeZoneInfo.ConvertTime(frame.To, local).ToString("HH:mm:ss", CultureInfo.InvariantCulture);
        var problems = frame.Stations.Select(s => s.Problem).OfType<string>().Select(p => (IRenderable)new Text(p, new Style(Color.Red)));
        var panels = frame.Panels.Select(p =>
        {
            var width = p.Rows.Count > 0 ? p.Rows[0].Length : 0;
            var lines = new List<IRenderable>();
            lines.AddRange(p.Rows.Select(r => new Text(r, new Style(p.Quality == "good" ? Color.Green : Color.Yellow))));
            lines.Add(new Text($"{from}{to.PadLeft(Math.Max(0, width - from.Length))}", new Style(Color.Grey)));
            lines.Add(new Text(Range(p), new Style(Color.Grey)));
            return (IRenderable)new Panel(new Rows(lines)) { Header = new PanelHeader($"{Markup.Escape(p.Name)}  {Markup.Escape(p.Value)}  ({p.Quality})"), Border = BoxBorder.Rounded };
        });
        return new Rows([.. problems, .. panels]);
    }

    /// <summary>The line under a chart: the window's range and its gaps, or that there was nothing to draw (never "0 .. 0" for no values).</summary>
    public static string Range(TrendPanel panel)
    {
        ArgumentNullException.ThrowIfNull(panel);
        if (panel.Min is not { } min || panel.Max is not { } max)
        {
            return "range none: no good value recorded in the window";
        }

        return $"range {TrendText.Number(min)} .. {TrendText.Number(max)}{(panel.Gaps > 0 ? $", {panel.Gaps} gap(s) (·: not recorded, stale or bad)" : string.Empty)}";
    }

    /// <summary>A console writing to <paramref name="output"/>: ANSI only on a terminal, so pipes and tests get plain text.</summary>
    /// <param name="output">Where it writes.</param>
    /// <param name="terminal">ANSI colours and the live redraw only on a terminal.</param>
    /// <param name="chartWidth">The chart's columns; the console is made wide enough for them and the panel's border.</param>
    public static IAnsiConsole ConsoleFor(TextWriter output, bool terminal, int chartWidth)
    {
        var console = AnsiConsole.Create(new AnsiConsoleSettings
        {
            Out = new AnsiConsoleOutput(output),
            Ansi = terminal ? AnsiSupport.Detect : AnsiSupport.No,
            ColorSystem = terminal ? ColorSystemSupport.Detect : ColorSystemSupport.NoColors,
            Interactive = terminal ? InteractionSupport.Detect : InteractionSupport.No,
        });
        console.Profile.Width = chartWidth + 4;
        return console;
    }
}
