using FluentAssertions;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Transport;
using OperatorPanel.Simulator.Reference;
using OperatorPanel.ViewModels.Session;
using OperatorPanel.ViewModels.Shell;
using OperatorPanel.ViewModels.Tests.Fakes;
using Xunit;

namespace OperatorPanel.ViewModels.Tests.Session;

/// <summary>Line > Read over PPI: a Freeport bus whose handler fell silent reconnects over PPI, the project file untouched.</summary>
public sealed class ReadOverPpiTests : IAsyncDisposable
{
    private PanelFixture? _fixture;
    private RecordingConnector _connector = null!;

    /// <summary>Made by <see cref="ConnectedAsync"/>: each test chooses the bus's baud.</summary>
    private PanelFixture Panel => _fixture!;

    public async ValueTask DisposeAsync()
    {
        if (_fixture is not null)
        {
            await _fixture.DisposeAsync();
        }
    }

    [Fact]
    public async Task ReadOverPpi_StationAnswering_NotOfferedUntilItFallsSilent()
    {
        var shell = await ConnectedAsync(9600);
        await Panel.RefreshAsync();

        Panel.Session.Stations.Single().Health.Should().Be(StationHealth.Online);
        shell.ReadOverPpiCommand.CanExecute(null).Should().BeFalse("the handler answers");
        shell.BackToFreeportCommand.CanExecute(null).Should().BeFalse();

        Panel.Plc.Mode = OperatingMode.Stop;
        await Panel.RefreshAsync();

        Panel.Session.Stations.Single().Health.Should().Be(StationHealth.Stopped);
        Panel.Session.SilentFreeportStation!.Name.Should().Be("Filler");
        shell.ReadOverPpiCommand.CanExecute(null).Should().BeTrue();
    }

    [Fact]
    public async Task ReadOverPpi_StoppedStationOverRadioModule_NotOffered()
    {
        var shell = await StoppedAsync(9600, LinkKind.RadioModule);

        shell.ReadOverPpiCommand.CanExecute(null).Should().BeFalse("the radio modules carry Freeport frames; PPI needs the cable");
        shell.Diagnostics.Stations.Single().ReadOverPpiCommand.CanExecute(null).Should().BeFalse();
    }

    [Theory]
    [InlineData(9600, 9600)]
    [InlineData(19200, 19200)]
    [InlineData(38400, 9600)]
    public async Task ReadOverPpi_StoppedStation_ReconnectsItsBusAsPpi8E1AtItsRateOr9600(int freeportBaud, int ppiBaud)
    {
        var shell = await StoppedAsync(freeportBaud);
        var saved = Panel.Session.Project;

        await shell.ReadOverPpiCommand.ExecuteAsync(null).Guarded();

        _connector.Projects.Should().HaveCount(2, "connected once over Freeport, once over PPI");
        _connector.Projects[1].Stations.Single().Link.Should().Be(new SerialSettings
        {
            PortName = PanelFixture.Port,
            BaudRate = ppiBaud,
            Parity = Parity.Even,
            DataBits = 8,
            StopBits = 1,
            Kind = LinkKind.Cable,
            Protocol = LinkProtocol.Ppi,
        });
        Panel.Session.IsConnected.Should().BeTrue();
        Panel.Session.IsReadingOverPpi.Should().BeTrue();
        Panel.Session.Stations.Single().IsPpi.Should().BeTrue();
        Panel.Session.SavedProject.Stations.Single().Should().Be(saved.Stations.Single(), "the project to save keeps its Freeport link");
        shell.IsDirty.Should().BeFalse("nothing in the project was edited");
        shell.ReadOverPpiCommand.CanExecute(null).Should().BeFalse();
        shell.BackToFreeportCommand.CanExecute(null).Should().BeTrue();
        shell.EditProjectCommand.CanExecute(null).Should().BeFalse("the wizard would take the PPI link for the project's");
        Panel.Session.StatusLine.Text.Should().Be(
            $"Filler: reading COM7 over PPI at {ppiBaud} baud 8E1 (a CPU whose port is set to another PPI rate in its system block will not answer) "
            + "while its handler does not answer; values are read and written, STOP and handler checks are off; Line > Back to Freeport returns");
    }

    [Fact]
    public async Task DiagnosticsRow_StoppedStation_OffersReadOverPpiAndSwitchesItsBus()
    {
        var shell = await ConnectedAsync(9600);
        await Panel.RefreshAsync();
        shell.Diagnostics.Stations.Single().ReadOverPpiCommand.CanExecute(null).Should().BeFalse("the handler answers");
        Panel.Plc.Mode = OperatingMode.Stop;
        await Panel.RefreshAsync();
        var row = shell.Diagnostics.Stations.Single();
        row.ReadOverPpiCommand.CanExecute(null).Should().BeTrue();

        await row.ReadOverPpiCommand.ExecuteAsync(null).Guarded();

        _connector.Projects[^1].Stations.Single().Link.Protocol.Should().Be(LinkProtocol.Ppi);
        shell.Diagnostics.Stations.Single().LinkText.Should().Contain("9600 8E1");
    }

    [Fact]
    public async Task BackToFreeport_AfterReadOverPpi_ReconnectsWithTheSavedLink()
    {
        var shell = await StoppedAsync(19200);
        var saved = Panel.Session.Project.Stations.Single().Link;
        await shell.ReadOverPpiCommand.ExecuteAsync(null).Guarded();

        await shell.BackToFreeportCommand.ExecuteAsync(null).Guarded();

        _connector.Projects.Should().HaveCount(3);
        _connector.Projects[2].Stations.Single().Link.Should().Be(saved);
        Panel.Session.Project.Stations.Single().Link.Should().Be(saved);
        Panel.Session.IsConnected.Should().BeTrue();
        Panel.Session.IsReadingOverPpi.Should().BeFalse();
        Panel.Session.Stations.Single().IsPpi.Should().BeFalse();
        shell.IsDirty.Should().BeFalse();
        shell.BackToFreeportCommand.CanExecute(null).Should().BeFalse();
        Panel.Session.StatusLine.Text.Should().Be("Back to Freeport: Filler 19200 8N1");
    }

    [Fact]
    public async Task SavedProject_EditedWhileReadOverPpi_KeepsTheEditAndTheFreeportLink()
    {
        var shell = await StoppedAsync(9600);
        var freeport = Panel.Session.Project.Stations.Single().Link;
        await shell.ReadOverPpiCommand.ExecuteAsync(null).Guarded();
        var station = Panel.Session.Project.Stations.Single();

        await Panel.Session.EditProjectAsync(Panel.Session.Project with { Stations = [station with { Tags = station.Tags.RemoveAt(0) }] }).Guarded();

        shell.IsDirty.Should().BeTrue();
        Panel.Session.Project.Stations.Single().Link.Protocol.Should().Be(LinkProtocol.Ppi, "the line still reads over PPI");
        Panel.Session.SavedProject.Stations.Single().Link.Should().Be(freeport);
        Panel.Session.SavedProject.Stations.Single().Tags.Select(t => t.Symbol).Should().Equal("Recipe", "Temperature");
    }

    private async Task<ShellViewModel> ConnectedAsync(int baud, LinkKind kind = LinkKind.Cable)
    {
        var project = PanelFixture.Project();
        var station = project.Stations.Single();
        _fixture = new PanelFixture(project with { Stations = [station with { Link = station.Link with { BaudRate = baud, Kind = kind } }] });
        _connector = new RecordingConnector(Panel.Connector);
        var shell = Panel.Shell();
        await Panel.Session.ConnectAsync(_connector).Guarded();
        return shell;
    }

    private async Task<ShellViewModel> StoppedAsync(int baud, LinkKind kind = LinkKind.Cable)
    {
        var shell = await ConnectedAsync(baud, kind);
        await Panel.RefreshAsync();
        Panel.Plc.Mode = OperatingMode.Stop;
        await Panel.RefreshAsync();
        Panel.Session.Stations.Single().Health.Should().Be(StationHealth.Stopped);
        return shell;
    }
}
