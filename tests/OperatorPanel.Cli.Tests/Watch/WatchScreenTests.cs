using OperatorPanel.Cli.Watch;
using Spectre.Console.Testing;

namespace OperatorPanel.Cli.Tests.Watch;

/// <summary>
/// watch on a terminal of any size: at 80x24 the title, each station's state and its alarms stay visible, lines are cut
/// (never wrapped) and lamps and tags give way, with a note saying so; at 200x24 nothing is cut that fits.
/// </summary>
public sealed class WatchScreenTests
{
    private const string Error = "station 2: serial port /dev/serial/by-id/usb-FTDI_FT232R_USB_UART_A50285BI-if00-port0: open failed: No such file or directory (ENOENT) - no such port";

    [Fact]
    public void Render_80x24_KeepsTitleStationStatesAndAlarmsAndCutsLongLines()
    {
        var lines = Draw(Snapshot(), 80, 24);

        lines.Should().HaveCountLessThanOrEqualTo(24);
        lines.Should().OnlyContain(l => l.Length <= 80, "long lines are cut, not wrapped");
        lines[0].Should().StartWith("Line 1  (continuous, at least 100 ms apart)  cycle 7");
        lines.Should().Contain(l => l.StartsWith("Filler  station 2", StringComparison.Ordinal) && l.Contains("offline", StringComparison.Ordinal));
        lines.Should().Contain(l => l.StartsWith("Capper  station 3", StringComparison.Ordinal) && l.Contains("online", StringComparison.Ordinal));
        lines.Should().Contain("  alarms   unknown: Filler offline (2 of 2 flags not read)");
        lines.Should().Contain(l => l.Contains("M2.2", StringComparison.Ordinal) && l.Contains("Low product level", StringComparison.Ordinal));
        lines.Should().Contain(l => l.StartsWith("  last error: station 2: serial port /dev/serial", StringComparison.Ordinal) && l.EndsWith('…'));
        lines[^1].Should().MatchRegex(@"^\(\d+ lines hidden: a taller window or --json shows all\)$");
    }

    [Fact]
    public void Render_200x24_CutsNothingThatFitsTheWidth()
    {
        var lines = Draw(Snapshot(), 200, 24);

        lines.Should().HaveCountLessThanOrEqualTo(24);
        lines.Should().Contain("  last error: " + Error);
        lines.Should().Contain(l => l.Contains("M2.2", StringComparison.Ordinal));
    }

    [Fact]
    public void Fit_EverythingFits_ShowsEveryLineAndNoNote()
    {
        var all = SnapshotRenderer.Lines(Snapshot());

        WatchScreen.Fit(all, all.Count).Should().Equal(all);
    }

    /// <summary>What a terminal of that size shows: the frame drawn into Spectre's test console, one string a row.</summary>
    private static List<string> Draw(WatchSnapshot snapshot, int width, int height)
    {
        var console = new TestConsole().Width(width);
        console.Write(WatchScreen.Render(snapshot, width, height));
        return [.. console.Output.TrimEnd('\n').Split('\n').Select(l => l.TrimEnd())];
    }

    private static WatchSnapshot Snapshot() => new(
        "Line 1",
        "continuous, at least 100 ms apart",
        7,
        new DateTimeOffset(2026, 11, 27, 9, 0, 0, TimeSpan.Zero),
        [
            Station("Filler", 2, "offline", Error, [new AlarmRow("M2.0", "Emergency stop pressed", "fault", AlarmRow.Unknown), new AlarmRow("M2.1", "Jam", "fault", AlarmRow.Unknown)]),
            Station("Capper", 3, "online", null, [new AlarmRow("M2.2", "Low product level in tank", "warning", AlarmRow.Active)]),
        ]);

    private static StationSnapshot Station(string name, int address, string state, string? error, IReadOnlyList<AlarmRow> alarms) =>
        new(name, address, "CPU 224", "/dev/ttyUSB0 9600 8N1", state, error, null, "ok: generated for CPU 224, protocol 2, mode switch RUN",
            new LinkView(40, 40, 0, 0, 12.5), Lamps("I"), Lamps("Q"),
            [.. Enumerable.Range(0, 12).Select(i => new TagRow($"Tag{i}", $"VW{2 * i}", "1234", "good"))], alarms)
        {
            AlarmsDefined = alarms.Count,
        };

    private static List<LampByte> Lamps(string area) =>
        [.. Enumerable.Range(0, 2).Select(b => new LampByte($"{area}B{b}", "●○●○●○●○",
            [.. Enumerable.Range(0, 8).Select(bit => new LampBit($"{area}{b}.{bit}", $"VeryLongSymbolName{b}{bit}", bit % 2 == 0, "good"))]))];
}
