using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Protocol;
using OperatorPanel.ViewModels.Shell;
using OperatorPanel.ViewModels.Tests.Fakes;
using OperatorPanel.ViewModels.Wizard;

namespace OperatorPanel.ViewModels.Tests.Shell;

public sealed class ShellWizardTests : IAsyncDisposable
{
    private readonly PanelFixture _panel = new();
    private readonly ScriptedWizardPresenter _presenter = new();
    private readonly FakeConnectionTester _tester = new();
    private readonly ShellViewModel _shell;

    public ShellWizardTests()
    {
        var ports = new FakePortCatalog();
        var services = new ShellServices(
            _panel.Dialogs, _panel.Files, _panel.Connector, null,
            new WizardProjectSource(_presenter, new PortInUseGuard(_tester, _panel.Session), ports), _presenter, _tester, ports);
        _shell = new ShellViewModel(_panel.Session, _panel.Options, services, _panel.Clock, _panel.Logger);
    }

    [Fact]
    public async Task New_WizardFinished_TheWizardsProjectOpenUnsaved()
    {
        _presenter.Operator = wizard =>
        {
            wizard.CpuStep.ProjectName = "Capper line";
            wizard.CpuStep.StationName = "Capper";
            wizard.CpuStep.StationAddress = "7";
            for (var i = 0; i < 4; i++)
            {
                wizard.NextCommand.Execute(null);
            }

            wizard.FinishCommand.Execute(null);
            return Task.CompletedTask;
        };

        await _shell.NewCommand.ExecuteAsync(null).Guarded();

        _presenter.Shown.Should().ContainSingle().Which.IsEditing.Should().BeFalse();
        _shell.Session.Project.Should().BeSameAs(_presenter.Shown[0].Result);
        _shell.Session.Project.Stations.Should().ContainSingle().Which.Address.Address.Should().Be(7);
        _shell.Title.Should().Be("Capper line * - Operator Panel");
        _shell.ProjectPath.Should().BeNull();
    }

    [Fact]
    public async Task New_WizardCancelled_CurrentProjectKept()
    {
        var project = _panel.Session.Project;
        _presenter.Cancel = true;

        await _shell.NewCommand.ExecuteAsync(null).Guarded();

        _panel.Session.Project.Should().BeSameAs(project);
        _shell.IsDirty.Should().BeFalse();
    }

    [Fact]
    public async Task EditProject_MemoryCellAdded_MarksDirtyAndPollsTheNewCell()
    {
        await _panel.ConnectAsync();
        _panel.Plc.Memory.WriteWord(ProtocolArea.V, 100, 77);
        _presenter.Operator = wizard =>
        {
            wizard.MemoryStep.Cells.Add(new MemoryCellRowViewModel("Count", "VW100", DisplayFormat.Signed));
            wizard.FinishCommand.Execute(null);
            return Task.CompletedTask;
        };

        await _shell.EditProjectCommand.ExecuteAsync(null).Guarded();
        await _panel.RefreshAsync();

        _presenter.Shown.Should().ContainSingle().Which.IsEditing.Should().BeTrue();
        _shell.IsDirty.Should().BeTrue();
        _shell.Title.Should().Be("Filler line * - Operator Panel");
        _panel.Session.Values.TryGetValue(PanelFixture.Filler, PlcAddress.Parse("VW100"), out var count).Should().BeTrue();
        count.Raw.Should().Equal(0, 77);
        _shell.Memory.Cells.Select(c => c.Symbol).Should().Contain("Count");
    }

    [Fact]
    public async Task EditProject_Cancelled_NothingChanges()
    {
        var project = _panel.Session.Project;
        _presenter.Cancel = true;

        await _shell.EditProjectCommand.ExecuteAsync(null).Guarded();

        _panel.Session.Project.Should().BeSameAs(project);
        _shell.IsDirty.Should().BeFalse();
    }

    [Fact]
    public async Task EditProject_TestConnectionOnTheConnectedPort_RefusedWithDisconnectFirst()
    {
        await _panel.ConnectAsync();
        _presenter.Cancel = true;
        _presenter.Operator = wizard => wizard.LinkStep.TestConnectionCommand.ExecuteAsync(null);

        await _shell.EditProjectCommand.ExecuteAsync(null).Guarded();

        var link = _presenter.Shown[0].LinkStep;
        link.TestSucceeded.Should().BeFalse();
        link.TestResult.Should().Be($"{PanelFixture.Port} could not be used: the panel is connected on {PanelFixture.Port}; choose Disconnect in the main window, then test again");
        _tester.Asked.Should().BeEmpty();
        _panel.Session.IsConnected.Should().BeTrue();
    }

    [Fact]
    public async Task EditProject_TestConnectionWhileDisconnected_AsksThePlc()
    {
        _tester.Reply = new ErrorResponse(PanelFixture.Filler, 1, CommandCode.Identify, ProtocolError.AddressOutOfRange);
        _presenter.Cancel = true;
        _presenter.Operator = wizard => wizard.LinkStep.TestConnectionCommand.ExecuteAsync(null);

        await _shell.EditProjectCommand.ExecuteAsync(null).Guarded();

        _tester.Asked.Should().ContainSingle().Which.Link.PortName.Should().Be(PanelFixture.Port);
    }

    public async ValueTask DisposeAsync()
    {
        _shell.Dispose();
        await _panel.DisposeAsync();
    }
}
