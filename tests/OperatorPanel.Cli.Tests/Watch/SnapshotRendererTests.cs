using OperatorPanel.Cli.Watch;

namespace OperatorPanel.Cli.Tests.Watch;

/// <summary>The station header of watch's text: the handler check, and a kept error told apart from a present one.</summary>
public sealed class SnapshotRendererTests
{
    private const string PortGone = "station 2: serial port COM3: read failed: the device vanished (unplugged?) - reconnecting";

    [Fact]
    public void Render_OnlineStationWithAKeptError_ShowsItAsEarlierNotAsThePresentState()
    {
        var text = SnapshotRenderer.Render(Snapshot(Station("online", PortGone, handler: "ok: generated for CPU 224, protocol 2, mode switch RUN")));

        text.Should().Contain($"  earlier error (it answers now): {PortGone}").And.NotContain("last error");
        text.Should().Contain("  handler  ok: generated for CPU 224, protocol 2, mode switch RUN");
    }

    [Fact]
    public void Render_OfflineStation_ShowsTheLastErrorAndNoHandlerLineBeforeIdentify()
    {
        var text = SnapshotRenderer.Render(Snapshot(Station("offline", PortGone, handler: null)));

        text.Should().Contain($"  last error: {PortGone}").And.NotContain("handler");
    }

    [Fact]
    public void Render_NameAndErrorWithControlCharacters_PrintsTheirCodesNeverTheCharacters()
    {
        var station = Station("offline", "no answer from \u001b[2Jstation 2", handler: null) with { Name = "Fil\u001b[31mler" };

        var text = SnapshotRenderer.Render(Snapshot(station));

        text.Should().NotContain("\u001b");
        text.Should().Contain("Fil<16#1B>[31mler  station 2").And.Contain("  last error: no answer from <16#1B>[2Jstation 2");
    }

    private static WatchSnapshot Snapshot(StationSnapshot station) =>
        new("Line", "continuous, at least 100 ms apart", 3, new DateTimeOffset(2026, 11, 25, 5, 0, 0, TimeSpan.Zero), [station]);

    private static StationSnapshot Station(string state, string? lastError, string? handler) =>
        new("Filler", 2, "CPU 224", "COM3 9600 8N1", state, lastError, null, handler, new LinkView(4, 3, 0, 1, 120.0), [], [], [], []);
}
