using OperatorPanel.Core.Audit;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Projects;
using OperatorPanel.Simulator.Reference;
using OperatorPanel.ViewModels.Diagnostics;
using OperatorPanel.ViewModels.Session;
using OperatorPanel.ViewModels.Tests.Fakes;

namespace OperatorPanel.ViewModels.Tests.Diagnostics;

/// <summary>
/// The Diagnostics row's Stop: offered only where the project allows STOP, the PLC's handler has it and writes are
/// allowed; always confirmed; afterwards the station shows "stopped by the panel", not offline.
/// </summary>
public sealed class StationStopTests : IAsyncDisposable
{
    private const string Question =
        "Put Filler (station 2) into STOP? Its program stops, so the line stops, and its port returns to PPI: "
        + "the panel cannot reach it until someone sets RUN (mode switch or Micro/WIN).";

    private PanelFixture _panel = null!;
    private DiagnosticsViewModel _diagnostics = null!;

    private StationDiagnosticsViewModel Row => _diagnostics.Stations.Single();

    private StationStatusViewModel Status => _panel.Session.Stations.Single();

    [Fact]
    public async Task StopCommand_ProjectAllowsAndHandlerHasStop_EnabledOnceConnectedAndIdentified()
    {
        Open(projectAllows: true, handlerHasStop: true);
        var beforeConnect = Row.StopCommand.CanExecute(null);

        await _panel.ConnectAsync();

        beforeConnect.Should().BeFalse();
        Status.Identity!.StopEnabled.Should().BeTrue();
        Row.StopCommand.CanExecute(null).Should().BeTrue();
    }

    [Theory]
    [InlineData(false, true)]
    [InlineData(true, false)]
    public async Task StopCommand_ProjectOrHandlerWithoutStop_Disabled(bool projectAllows, bool handlerHasStop)
    {
        Open(projectAllows, handlerHasStop);

        await _panel.ConnectAsync();

        Row.StopCommand.CanExecute(null).Should().BeFalse();
    }

    [Fact]
    public async Task StopCommand_ReadOnly_DisabledAndTheSessionRefusesToo()
    {
        Open(projectAllows: true, handlerHasStop: true);
        await _panel.ConnectAsync();
        var changes = 0;
        Row.StopCommand.CanExecuteChanged += (_, _) => changes++;

        _panel.Session.IsReadOnly = true;
        var framesBefore = _panel.Transport.FramesSent;
        var refused = await _panel.Session.StopAsync(PanelFixture.Filler);

        changes.Should().BeGreaterThan(0);
        Row.StopCommand.CanExecute(null).Should().BeFalse();
        refused.Text.Should().Be("station 2: STOP not sent: read-only mode, nothing sent");
        _panel.Transport.FramesSent.Should().Be(framesBefore);
        _panel.Plc.Mode.Should().Be(OperatingMode.Run);
    }

    [Fact]
    public async Task Stop_ConfirmationDeclined_SendsNothing()
    {
        Open(projectAllows: true, handlerHasStop: true);
        await _panel.ConnectAsync();
        var framesBefore = _panel.Transport.FramesSent;
        _panel.Dialogs.ConfirmAnswers.Enqueue(false);

        await Row.StopCommand.ExecuteAsync(null).Guarded();

        _panel.Dialogs.Questions.Should().Equal(Question);
        _panel.Dialogs.NoByDefault.Should().Equal([true], "No is the default button of Stop PLC: Enter does not stop the line");
        _panel.Transport.FramesSent.Should().Be(framesBefore);
        _panel.Plc.Mode.Should().Be(OperatingMode.Run);
        Status.Health.Should().NotBe(StationHealth.StoppedByPanel);
    }

    [Fact]
    public async Task Stop_Confirmed_PlcInStopAndStationShownStoppedByThePanel()
    {
        Open(projectAllows: true, handlerHasStop: true);
        await _panel.ConnectAsync();
        await _panel.RefreshAsync();
        _panel.Dialogs.ConfirmAnswers.Enqueue(true);

        await Row.StopCommand.ExecuteAsync(null).Guarded();
        await _panel.RefreshAsync();

        _panel.Plc.Mode.Should().Be(OperatingMode.Stop);
        Status.Health.Should().Be(StationHealth.StoppedByPanel);
        Status.HealthText.Should().Be("stopped by the panel: the port speaks PPI until someone sets RUN");
        Row.RunStopText.Should().Be("STOP (by the panel)");
        Row.StopCommand.CanExecute(null).Should().BeFalse("it is stopped already");
        _panel.Session.StatusLine.Text.Should().Be("station 2 stopped: the port speaks PPI until someone sets RUN");
        _panel.Log.Events.Select(e => e.RenderMessage()).Should().Contain("Station 2 RUN -> STOP by operator: sending STOP");
    }

    [Fact]
    public async Task Stop_Confirmed_IntentOnRecordBeforeItIsSentAndOutcomeAfter()
    {
        Open(projectAllows: true, handlerHasStop: true);
        OperatingMode? modeAtIntent = null;
        var trail = new RecordingAuditTrail(e => modeAtIntent ??= e.Step == AuditStep.Intent ? _panel.Plc.Mode : null);
        _panel.Session.Audit = trail;
        await _panel.ConnectAsync();
        _panel.Dialogs.ConfirmAnswers.Enqueue(true);

        await Row.StopCommand.ExecuteAsync(null).Guarded();

        trail.Entries.Select(e => (e.Step, e.Action, e.Port, e.Target, e.OldValue, e.NewValue, e.Outcome, e.User)).Should().Equal(
            (AuditStep.Intent, AuditAction.Stop, PanelFixture.Port, (string?)null, "RUN", "STOP", (string?)null, _panel.Session.User),
            (AuditStep.Outcome, AuditAction.Stop, PanelFixture.Port, null, "RUN", "STOP", "station 2 stopped: the port speaks PPI until someone sets RUN", _panel.Session.User));
        trail.Entries[0].Id.Should().Be(trail.Entries[1].Id);
        modeAtIntent.Should().Be(OperatingMode.Run, "the intent is on record before STOP is sent");
    }

    [Fact]
    public async Task Stop_StationSetToRunAgain_OnlineAndStopOfferedAgain()
    {
        Open(projectAllows: true, handlerHasStop: true);
        await _panel.ConnectAsync();
        _panel.Dialogs.ConfirmAnswers.Enqueue(true);
        await Row.StopCommand.ExecuteAsync(null).Guarded();

        _panel.Plc.Mode = OperatingMode.Run;
        await _panel.RefreshAsync();

        Status.Health.Should().Be(StationHealth.Online);
        Row.StopCommand.CanExecute(null).Should().BeTrue();
    }

    [Fact]
    public async Task Connect_StationRunsAV1Handler_ShowsRegenerateThePlcCode()
    {
        Open(projectAllows: false, handlerHasStop: false);
        _panel.Connector.V1Handler = PanelFixture.Filler;

        await _panel.ConnectAsync();
        await _panel.RefreshAsync();

        Status.Health.Should().Be(StationHealth.HandlerOutdated);
        Status.HealthText.Should().Be("handler of an older protocol (the panel speaks v3): regenerate the PLC code (File > Generate PLC code) and download it");
        Status.IdentifyError.Should().Be("IDENTIFY: HandlerOutdated: station 2 runs an Operator Panel handler of protocol v1, but the panel speaks protocol v3: regenerate the PLC code (opanel generate) and download it");
    }

    public async ValueTask DisposeAsync() => await _panel.DisposeAsync();

    private void Open(bool projectAllows, bool handlerHasStop)
    {
        var project = PanelFixture.Project();
        _panel = new PanelFixture(project with { Stations = [project.Stations[0] with { AllowStop = projectAllows }] });
        _panel.Connector.Configure(new HandlerConfig(PanelFixture.Filler, CpuProfiles.For(CpuModel.Cpu224), allowStop: handlerHasStop));
        _diagnostics = new DiagnosticsViewModel(_panel.Session, _panel.Dialogs);
    }
}
