using System.Globalization;
using System.Text;

namespace OperatorPanel.Cli.Trend;

/// <summary>
/// Draws a trend's columns as rows of block characters (eighths of a cell: ▁▂▃▄▅▆▇█), the band from each column's lowest
/// to highest value filled, scaled to the window's own range; a gap is a '·' on the bottom row. Plain text, so a pipe or a
/// test reads exactly what the terminal shows. A window without a single good value has no range (null): 0 .. 0 would
/// read as a value that was recorded.
/// </summary>
internal static class TrendText
{
    private const string Eighths = " ▁▂▃▄▅▆▇█";

    public static IReadOnlyList<string> Draw((double Low, double High)?[] columns, int height, out double? min, out double? max)
    {
        ArgumentNullException.ThrowIfNull(columns);
        var known = columns.Where(c => c is not null).Select(c => c!.Value).ToList();
        min = known.Count > 0 ? known.Min(c => c.Low) : null;
        max = known.Count > 0 ? known.Max(c => c.High) : null;
        var (low, span) = (min ?? 0, (max ?? 0) - (min ?? 0));
        var rows = Enumerable.Range(0, height).Select(_ => new StringBuilder()).ToArray();
        foreach (var column in columns)
        {
            if (column is not { } c)
            {
                for (var r = 0; r < height; r++)
                {
                    rows[r].Append(r == height - 1 ? '·' : ' ');
                }

                continue;
            }

            // In eighths from the bottom: the band's top, and its bottom (at least one eighth high, so a flat line shows).
            var top = span > 0 ? (int)Math.Round((c.High - low) / span * ((height * 8) - 1)) + 1 : (height * 4);
            var bottom = span > 0 ? (int)Math.Round((c.Low - low) / span * ((height * 8) - 1)) : top - 1;
            for (var r = 0; r < height; r++)
            {
                var cellBase = (height - 1 - r) * 8;
                var filled = Math.Clamp(top - cellBase, 0, 8);
                var below = Math.Clamp(bottom - cellBase, 0, 8);
                // A cell wholly under the band's bottom stays empty: the band floats at its values, like a line.
                rows[r].Append(filled == 0 || below >= 8 ? ' ' : Eighths[filled]);
            }
        }

        return [.. rows.Select(r => r.ToString())];
    }

    /// <summary>A value as the axis labels print it: up to 4 significant decimals, invariant culture.</summary>
    public static string Number(double value) => value.ToString("0.####", CultureInfo.InvariantCulture);
}
