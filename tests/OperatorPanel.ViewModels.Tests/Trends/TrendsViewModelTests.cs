using OperatorPanel.Core.Protocol;
using OperatorPanel.Historian.Reading;
using OperatorPanel.ViewModels.Shell;
using OperatorPanel.ViewModels.Tests.Fakes;
using OperatorPanel.ViewModels.Trends;

namespace OperatorPanel.ViewModels.Tests.Trends;

/// <summary>The Trends window: what it plots from the history, its window (live, ranges, zoom, pan) and its cursor.</summary>
public sealed class TrendsViewModelTests : IAsyncDisposable
{
    private readonly PanelFixture _panel = new();
    private readonly ShellViewModel _shell;
    private readonly TempFolder _folder = new();

    public TrendsViewModelTests() => _shell = _panel.Shell();

    private TrendsViewModel Trends => _shell.Trends;

    [Fact]
    public async Task Plot_LiveLine_DrawsThePickedTagsFromTheHistoryWithTheUnrecordedPastAsAGap()
    {
        await ConnectedAsync();
        _panel.Plc.Memory.WriteWord(ProtocolArea.V, 10, 1234);
        await _panel.RefreshAsync();
        _panel.Clock.Advance(TimeSpan.FromSeconds(5));

        await Trends.RefreshAsync();

        Trends.Picked.Select(t => t.Name).Should().Equal("Filler.Speed", "Filler.Recipe", "Filler.Temperature");
        var speed = Trends.Plot.Lanes[0];
        speed.Name.Should().Be("Filler.Speed");
        speed.Segments.Should().ContainSingle().Which.Points[^1].Should().Be(new TrendPoint(_panel.Clock.GetUtcNow(), 1234));
        speed.Gaps[0].Kind.Should().Be(TrendGapKind.NotRecorded, "nothing was recorded before the project was saved");
        Trends.Plot.IsLive.Should().BeTrue();
        Trends.Plot.To.Should().Be(_panel.Clock.GetUtcNow());
        Trends.Picked.First().ValueText.Should().Be("1234 (good)");
    }

    [Fact]
    public async Task Pick_AnotherTag_AddsItsLane()
    {
        await ConnectedAsync();
        var input = Trends.Tags.Single(t => t.Name == "Filler.StartButton");

        input.IsSelected = true;
        await Trends.RefreshAsync();

        Trends.Plot.Lanes.Select(l => l.Name).Should().Contain("Filler.StartButton");
        Trends.Plot.Lanes.Single(l => l.Name == "Filler.StartButton").IsBit.Should().BeTrue();
    }

    [Fact]
    public async Task Zoom_WhileLive_ChangesTheSpanAndStaysLive()
    {
        await ConnectedAsync();

        Trends.Zoom(0.5, 0.3);
        await Trends.RefreshAsync();

        Trends.IsLive.Should().BeTrue();
        (Trends.Plot.To - Trends.Plot.From).Should().Be(TimeSpan.FromMinutes(5));
    }

    [Fact]
    public async Task Pan_IntoThePast_LeavesLiveAndNeverGoesPastNow()
    {
        await ConnectedAsync();
        var now = _panel.Clock.GetUtcNow();

        Trends.Pan(-0.5);
        Trends.IsLive.Should().BeFalse();
        Trends.To.Should().Be(now.AddMinutes(-5));

        Trends.Pan(2);
        Trends.To.Should().Be(now, "a pan stops at now");
        Trends.BackToLiveCommand.CanExecute(null).Should().BeTrue();
    }

    [Fact]
    public async Task Range_Shift_IsTheLastEightHours()
    {
        await ConnectedAsync();

        Trends.Range = TrendRange.Shift;
        await Trends.RefreshAsync();

        (Trends.Plot.To - Trends.Plot.From).Should().Be(TimeSpan.FromHours(8));
        Trends.Plot.IsLive.Should().BeFalse();
    }

    [Fact]
    public async Task Cursor_ReadsEachTagsValueOrWhyThereIsNone()
    {
        await ConnectedAsync();
        _panel.Plc.Memory.WriteWord(ProtocolArea.V, 10, 77);
        await _panel.RefreshAsync();
        _panel.Clock.Advance(TimeSpan.FromSeconds(30));
        await Trends.RefreshAsync();
        var speed = Trends.Picked.First();

        Trends.PointAt(0.999);
        speed.CursorText.Should().Be("77 (good)");
        Trends.PointAt(0.1);
        speed.CursorText.Should().Be("not recorded");
        Trends.ClearCursorCommand.Execute(null);
        speed.CursorText.Should().BeEmpty();
    }

    [Fact]
    public void Build_DayOfFastChanges_IsThinnedKeepingTheLanesPeak()
    {
        var t0 = _panel.Clock.GetUtcNow();
        var rows = Enumerable.Range(0, 50_000).Select(i => new HistorySample(t0.AddMilliseconds(100 * i), i == 31_337 ? 30_000 : i % 7, Core.Polling.ValueQuality.Good)).ToList();
        var history = new TagHistory(PanelFixture.Filler, Core.Addressing.PlcAddress.Parse("VW10"), "Speed", Core.Projects.DisplayFormat.Signed, rows);
        var end = t0.AddMilliseconds(100 * 50_000);

        var plot = TrendPlotBuilder.Build([Trends.Tags[0]], [history], [new RecordingSpan(t0, end, "test")], t0, end, null, null);

        var points = plot.Lanes[0].Segments.SelectMany(s => s.Points).ToList();
        points.Count.Should().BeLessThanOrEqualTo(TrendPlotBuilder.MaxPointsPerLane + 1);
        plot.Lanes[0].Max.Should().Be(30_000, "thinning keeps each slice's highest point");
        points[^1].At.Should().Be(end);
    }

    public async ValueTask DisposeAsync()
    {
        await _shell.CloseAsync();
        _shell.Dispose();
        await _panel.DisposeAsync();
        _folder.Dispose();
    }

    private async Task ConnectedAsync()
    {
        _panel.Files.FileToSave = _folder.File("filler.opproj");
        await _shell.SaveAsCommand.ExecuteAsync(null).Guarded();
        await _panel.ConnectAsync();
        await _panel.RefreshAsync();
    }
}
