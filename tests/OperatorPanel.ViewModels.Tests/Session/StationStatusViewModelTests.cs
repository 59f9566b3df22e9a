using OperatorPanel.Core.Link;
using OperatorPanel.Core.Polling;
using OperatorPanel.ViewModels.Session;
using OperatorPanel.ViewModels.Tests.Fakes;

namespace OperatorPanel.ViewModels.Tests.Session;

public sealed class StationStatusViewModelTests
{
    private readonly StationStatusViewModel _station = new(PanelFixture.Project().Stations[0]);

    [Fact]
    public void HealthText_LineOpenNotReadYet_SaysSoNotThatItIsNotConnected()
    {
        _station.HealthText.Should().Be("not connected");

        _station.Update(StationStatus.Initial(PanelFixture.Filler), LinkStatistics.Empty);

        _station.HealthText.Should().Be("not read yet", "the status line says the line is polling it");
        _station.Update(null, LinkStatistics.Empty);
        _station.HealthText.Should().Be("not connected");
    }

    [Fact]
    public void PortText_ShowsPortBaudAndLineSettings()
    {
        _station.PortText.Should().Be("COM7 9600 8N1");
    }
}
