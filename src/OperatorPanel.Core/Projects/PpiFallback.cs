using System.Globalization;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Core.Projects;

/// <summary>
/// "Read over PPI": a Freeport bus switched in memory to PPI (docs/ppi.md section 14), for stations whose handler is
/// silent (STOP, TERM) while their CPU still answers its own protocol. The project file is never touched: the switched
/// project is only what the line connects with.
/// </summary>
public static class PpiFallback
{
    /// <summary>The S7-200's PPI rates (seed 002, Tables ), as a project's PPI link allows them.</summary>
    public static IReadOnlyList<int> Rates => LinkReader.PpiRates;

    /// <summary>
    /// The PPI rate to try on <paramref name="link"/>: its own baud when that is a PPI rate (seed 002, Tables ),
    /// else 9600, the CPU's default PPI rate. The CPU's rate is in its system block, so a guess may meet silence.
    /// </summary>
    public static int BaudFor(SerialSettings link)
    {
        ArgumentNullException.ThrowIfNull(link);
        return Rates.Contains(link.BaudRate) ? link.BaudRate : 9600;
    }

    /// <summary>The same port as PPI: 8 data bits, even parity, one stop bit, the cable, at <paramref name="baud"/>.</summary>
    public static SerialSettings Of(SerialSettings link, int? baud = null)
    {
        ArgumentNullException.ThrowIfNull(link);
        return link with
        {
            BaudRate = baud ?? BaudFor(link),
            Parity = Parity.Even,
            DataBits = 8,
            StopBits = 1,
            Kind = LinkKind.Cable,
            Protocol = LinkProtocol.Ppi,
        };
    }

    /// <summary>
    /// <paramref name="project"/> with every station on <paramref name="portName"/> (its whole bus: one port, one
    /// protocol) switched to PPI; every bus when <paramref name="portName"/> is null.
    /// </summary>
    public static PanelProject Switch(PanelProject project, string? portName, int? baud = null)
    {
        ArgumentNullException.ThrowIfNull(project);
        return project with
        {
            Stations = [.. project.Stations.Select(s => portName is null || OnPort(s, portName) ? s with { Link = Of(s.Link, baud) } : s)],
        };
    }

    /// <summary>
    /// <paramref name="current"/> (perhaps edited while read over PPI) with each station's link as in <paramref name="saved"/>:
    /// the project to save and to reconnect over Freeport.
    /// </summary>
    public static PanelProject Restore(PanelProject current, PanelProject saved)
    {
        ArgumentNullException.ThrowIfNull(current);
        ArgumentNullException.ThrowIfNull(saved);
        var links = saved.Stations.ToDictionary(s => s.Name, s => s.Link, StringComparer.Ordinal);
        return current with
        {
            Stations = [.. current.Stations.Select(s => links.TryGetValue(s.Name, out var link) ? s with { Link = link } : s)],
        };
    }

    /// <summary>"9600 baud (a CPU whose PPI port is set otherwise will not answer)": what the status line and watch say.</summary>
    public static string DescribeBaud(int baud) =>
        string.Create(CultureInfo.InvariantCulture, $"{baud} baud 8E1 (a CPU whose port is set to another PPI rate in its system block will not answer)");

    private static bool OnPort(ProjectStation station, string portName) =>
        string.Equals(station.Link.PortName, portName, StringComparison.OrdinalIgnoreCase);
}
