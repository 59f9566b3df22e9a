using System.Globalization;
using Spectre.Console;
using Spectre.Console.Rendering;

namespace OperatorPanel.Cli.Trend;

/// <summary>
/// A frame as Spectre.Console renders it: a panel per tag with its value now, the chart rows and the window's range and
/// times under it. Colour only where the console has it; the characters are the same either way.
/// </summary>
internal static class TrendRenderer
{
    public static IRenderable Render(TrendFrame frame)
    {
        ArgumentNullException.ThrowIfNull(frame);
        var local = TimeZoneInfo.Local;
        var from = TimeZoneInfo.ConvertTime(frame.From, local).ToString("HH:mm:ss", CultureInfo.InvariantCulture);
        var to = TimeZoneInfo.ConvertTime(frame.To, local).ToString("HH:mm:ss", CultureInfo.InvariantCulture);
        var panels = frame.Panels.Select(p =>
        {
            var width = p.Rows.Count > 0 ? p.Rows[0].Length : 0;
            var lines = new List<IRenderable>();
            lines.AddRange(p.Rows.Select(r => new Text(r, new Style(p.Quality == "good" ? Color.Green : Color.Yellow))));
            lines.Add(new Text($"{from}{to.PadLeft(Math.Max(0, width - from.Length))}", new Style(Color.Grey)));
            lines.Add(new Text($"range {TrendText.Number(p.Min)} .. {TrendText.Number(p.Max)}{(p.Gaps > 0 ? $", {p.Gaps} gap(s) (·: not recorded, stale or bad)" : string.Empty)}", new Style(Color.Grey)));
            return new Panel(new Rows(lines)) { Header = new PanelHeader($"{Markup.Escape(p.Name)}  {Markup.Escape(p.Value)}  ({p.Quality})"), Border = BoxBorder.Rounded };
        });
        return new Rows(panels);
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
