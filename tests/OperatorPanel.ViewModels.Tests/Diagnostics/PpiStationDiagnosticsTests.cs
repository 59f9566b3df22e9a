using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Ppi;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Transport;
using OperatorPanel.ViewModels.Diagnostics;
using OperatorPanel.ViewModels.Session;
using OperatorPanel.ViewModels.Tests.Fakes;

namespace OperatorPanel.ViewModels.Tests.Diagnostics;

/// <summary>A station of a PPI bus in Diagnostics: no handler, SMB6 and scan times from the PPI identify, RUN/STOP unknown.</summary>
public sealed class PpiStationDiagnosticsTests : IAsyncDisposable
{
    private readonly PanelFixture _panel = new();

    [Fact]
    public void Station_PpiIdentified_ShowsWhatPpiTellsAndRunStopUnknown()
    {
        var status = new StationStatusViewModel(PpiStation());
        var row = new StationDiagnosticsViewModel(status, _panel.Session, _panel.Dialogs);

        status.NotePpiIdentify(new PpiIdentifyOutcome(new PpiIdentity(new Station(2), 0x20, SwitchAtRun: false, 7, 5, 11), null));
        status.Update(StationStatus.Initial(new Station(2)) with { State = StationState.Offline, LastError = "NoAnswer: silent" }, Core.Link.LinkStatistics.Empty);

        row.LinkText.Should().Be("COM3 19200 8E1, cable, PPI, no handler");
        row.HandlerText.Should().Be("none needed: the bus speaks PPI");
        row.Smb6Text.Should().Be("16#20");
        row.PlcCpuText.Should().Be("SMB6 16#20 (read over PPI)");
        row.RunStopText.Should().Be("unknown over PPI (mode switch at TERM)");
        row.ScanTimesText.Should().Be("last 7 ms, min 5 ms, max 11 ms");
        status.Health.Should().Be(StationHealth.Offline, "a CPU answers PPI in STOP too, so its silence is not a STOP");
    }

    [Fact]
    public void Station_PpiIdentifyFailed_SaysWhy()
    {
        var status = new StationStatusViewModel(PpiStation());

        status.NotePpiIdentify(new PpiIdentifyOutcome(null, "station 2 did not answer the job"));

        status.IdentifyError.Should().Be("PPI identify: station 2 did not answer the job");
        status.PpiIdentity.Should().BeNull();
    }

    public ValueTask DisposeAsync() => _panel.DisposeAsync();

    private static ProjectStation PpiStation()
    {
        var station = StarterProject.Create("Line", CpuProfiles.For(CpuModel.Cpu224), new Station(2), "COM3").Stations[0];
        return station with { Link = station.Link with { BaudRate = 19200, Parity = Parity.Even, Protocol = LinkProtocol.Ppi } };
    }
}
