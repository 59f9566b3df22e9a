using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Simulator.Reference;
using OperatorPanel.ViewModels.Diagnostics;
using OperatorPanel.ViewModels.Tests.Fakes;

namespace OperatorPanel.ViewModels.Tests.Diagnostics;

public sealed class DiagnosticsViewModelTests : IAsyncDisposable
{
    private readonly PanelFixture _panel = new();
    private readonly DiagnosticsViewModel _diagnostics;

    public DiagnosticsViewModelTests() => _diagnostics = new DiagnosticsViewModel(_panel.Session, _panel.Dialogs);

    [Fact]
    public async Task Identify_AfterScans_ShowsCpuRunScanTimesAndStatistics()
    {
        await _panel.ConnectAsync();
        var scans = new Simulator.Hosting.V3DemoStation(_panel.Plc);
        scans.CompleteScan(12);
        scans.CompleteScan(9);

        await _diagnostics.IdentifyCommand.ExecuteAsync(null).Guarded();
        await _panel.RefreshAsync();

        var station = _diagnostics.Stations.Should().ContainSingle().Subject;
        station.ProjectCpuText.Should().Be("CPU 224");
        station.LinkText.Should().Be("COM7 9600 8N1, cable, Freeport handler");
        station.PlcCpuText.Should().Be("CPU 224");
        station.CpuMismatch.Should().BeFalse();
        station.Smb6Text.Should().Be("16#" + _panel.Plc.Memory.SM[6].ToString("X2", System.Globalization.CultureInfo.InvariantCulture));
        station.HandlerText.Should().Be("protocol 3, handler revision 1, full");
        station.HandlerShapeText.Should().Be("FEATURES 16#02 (list); list of 32 items, 128 bytes; requests up to 137 bytes; END_TIMEOUT_MS 4; own V bytes VB7586-VB8191");
        station.RunStopText.Should().Be("RUN");
        station.ScanTimesText.Should().Be("last 9 ms, min 9 ms, max 12 ms");
        station.StatisticsText.Should().StartWith($"{_panel.Transport.FramesSent} requests, {_panel.Transport.FramesSent} replies, 0 retries");
    }

    [Fact]
    public async Task Station_WentToStop_RunStopSaysSo()
    {
        await _panel.ConnectAsync();
        await _panel.RefreshAsync();
        _panel.Plc.Mode = OperatingMode.Stop;

        await _panel.RefreshAsync();

        _diagnostics.Stations.Single().RunStopText.Should().Be("STOP or TERM (no Freeport reply)");
    }

    [Fact]
    public void Station_RestingBetweenTries_SaysWhyAndWhenItIsTriedNext()
    {
        var station = _diagnostics.Stations.Single();
        var next = new DateTimeOffset(2026, 11, 25, 8, 30, 15, TimeSpan.Zero);

        station.Status.Update(
            new StationStatus(station.Status.Address, StationState.Offline, "NoAnswer: silent", 3, null, next.AddSeconds(-5), next),
            Core.Link.LinkStatistics.Empty);

        station.RetryText.Should().Be(
            $"Silent while other stations on its bus answer: tried again at {next.ToLocalTime():HH:mm:ss}, not every cycle, so it does not slow their refresh.");
        station.Status.Update(new StationStatus(station.Status.Address, StationState.Online, null, 0, next), Core.Link.LinkStatistics.Empty);
        station.RetryText.Should().BeEmpty();
    }

    [Fact]
    public void Identify_NotConnected_Disabled()
    {
        _diagnostics.IdentifyCommand.CanExecute(null).Should().BeFalse();
        _diagnostics.Stations.Single().PlcCpuText.Should().Be("not identified yet");
    }

    public async ValueTask DisposeAsync() => await _panel.DisposeAsync();
}
