using OperatorPanel.Core.Protocol;
using OperatorPanel.Simulator.Reference;
using OperatorPanel.ViewModels.Inputs;
using OperatorPanel.ViewModels.Outputs;
using OperatorPanel.ViewModels.Tests.Fakes;

namespace OperatorPanel.ViewModels.Tests.Outputs;

public sealed class OutputsViewModelTests : IAsyncDisposable
{
    private readonly PanelFixture _panel = new();
    private readonly OutputsViewModel _outputs;

    public OutputsViewModelTests() => _outputs = new OutputsViewModel(_panel.Session, _panel.Dialogs, _panel.Options, _panel.Logger);

    private OutputViewModel Conveyor => _outputs.Groups.Single().Points.Single(p => p.Symbol == "Conveyor");

    [Fact]
    public async Task Switch_WriteOnTheWire_LampStaysOffUntilTheReadBack()
    {
        await ConnectAndRefreshAsync();
        Conveyor.State.Should().Be(LampState.Off);
        var held = _panel.Transport.HoldNextReply();

        var click = Conveyor.SwitchCommand.ExecuteAsync(null);
        await held.Guarded();

        _panel.Plc.Memory.GetBit(ProtocolArea.Q, 0, 0).Should().BeTrue("the PLC has the write");
        Conveyor.Value.Should().BeFalse("the lamp follows the read-back, not the click");
        Conveyor.State.Should().Be(LampState.Off);
        Conveyor.IsWriting.Should().BeTrue();

        _panel.Transport.Release();
        await click.Guarded();

        Conveyor.State.Should().Be(LampState.On);
        Conveyor.IsWriting.Should().BeFalse();
        Conveyor.WriteError.Should().BeNull();
        _panel.Session.StatusLine.Text.Should().Be("Q0.0 (Conveyor): 1 written and confirmed by the PLC");
    }

    [Fact]
    public async Task Switch_PlcRefusesTheWrite_ShownOnRowAndStatusLine()
    {
        _panel.Connector.Configure(new HandlerConfig(PanelFixture.Filler, PanelFixture.Project().Stations[0].Cpu, writeMask: 0x38)); // M, V, SM: no Q
        await ConnectAndRefreshAsync();

        await Conveyor.SwitchCommand.ExecuteAsync(null).Guarded();

        Conveyor.State.Should().Be(LampState.Off);
        Conveyor.WriteError.Should().Be("station 2 refused the write: 83: the PLC refuses writes there (inputs, SM, an area the handler's write mask leaves out, or the handler's own V bytes)");
        _panel.Session.StatusLine.IsError.Should().BeTrue();
        _panel.Session.StatusLine.Text.Should().Be("Q0.0 (Conveyor): write of 1 not confirmed: station 2 refused the write: 83: the PLC refuses writes there (inputs, SM, an area the handler's write mask leaves out, or the handler's own V bytes)");
    }

    [Fact]
    public async Task Switch_ProgramResetsTheOutputAtOnce_MismatchShownAndLampOff()
    {
        await ConnectAndRefreshAsync();
        _panel.Transport.RewriteReply = ReadBackZero;

        await Conveyor.SwitchCommand.ExecuteAsync(null).Guarded();

        Conveyor.State.Should().Be(LampState.Off);
        Conveyor.WriteError.Should().Be("wrote 1, the PLC read back 0: its program changed it at once");
        _panel.Session.StatusLine.IsError.Should().BeTrue();
        _panel.Session.StatusLine.Text.Should().StartWith("Q0.0 (Conveyor): write of 1 not confirmed");
    }

    [Fact]
    public async Task Switch_ReadOnlyMode_DisabledAndNothingSent()
    {
        await ConnectAndRefreshAsync();
        _panel.Session.IsReadOnly = true;
        var frames = _panel.Transport.FramesSent;

        Conveyor.SwitchCommand.CanExecute(null).Should().BeFalse();
        await Conveyor.SwitchCommand.ExecuteAsync(null).Guarded();
        var direct = await _panel.Session.WriteAsync(Core.Writes.WriteRequest.Bit(PanelFixture.Filler, Conveyor.PlcAddress, true)).Guarded();

        _panel.Transport.FramesSent.Should().Be(frames);
        direct.Should().BeOfType<Core.Writes.WriteOutcome.Failed>().Which.Reason.Should().Be("Q0.0: read-only mode, nothing written");
        _panel.Plc.Memory.GetBit(ProtocolArea.Q, 0, 0).Should().BeFalse();
    }

    [Fact]
    public async Task Switch_ConfirmationAskedAndDeclined_NothingSent()
    {
        _panel.Options.ConfirmWrites = true;
        await ConnectAndRefreshAsync();
        var frames = _panel.Transport.FramesSent;
        _panel.Dialogs.ConfirmAnswers.Enqueue(false);

        await Conveyor.SwitchCommand.ExecuteAsync(null).Guarded();

        _panel.Dialogs.Questions.Should().Equal("Set Q0.0 (Conveyor) from 0 to 1?");
        _panel.Dialogs.NoByDefault.Should().Equal(false);
        _panel.Transport.FramesSent.Should().Be(frames);
    }

    [Fact]
    public void Options_NewOperator_ConfirmsWritesByDefault()
    {
        new OperatorPanel.ViewModels.Session.PanelOptions().ConfirmWrites.Should().BeTrue("one click must not switch an output of a running line");
    }

    [Fact]
    public async Task Switch_Confirmed_LoggedOnceWithOldAndNewValue()
    {
        await ConnectAndRefreshAsync();

        await Conveyor.SwitchCommand.ExecuteAsync(null).Guarded();

        _panel.Log.Messages.Where(m => m.StartsWith("Write ", StringComparison.Ordinal))
            .Should().Equal("Write station 2 Q0.0: 0 -> 1 confirmed");
    }

    [Fact]
    public async Task Switch_NotConnected_Disabled()
    {
        await Task.CompletedTask;

        Conveyor.SwitchCommand.CanExecute(null).Should().BeFalse();
        _outputs.OverwriteWarning.Should().Contain("next scan");
    }

    public async ValueTask DisposeAsync() => await _panel.DisposeAsync();

    private async Task ConnectAndRefreshAsync()
    {
        await _panel.ConnectAsync();
        await _panel.RefreshAsync();
    }

    /// <summary>The WRITE BIT reply as if the PLC program had reset QB0 before the read-back.</summary>
    /// <summary>A one-byte read-back (WRITE BITS' reply: STATUS 80, REQCHECK kept) turned to 0, its check made good again.</summary>
    private static byte[] ReadBackZero(byte[] reply)
    {
        Core.Protocol.V3.Codec.TryDecodeReply(reply, out var decoded, out _).Should().BeTrue();
        return decoded.Payload.Length == 1 ? Core.Protocol.V3.Codec.Encode(decoded with { Payload = [0x00] }) : reply;
    }
}
