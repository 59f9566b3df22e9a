using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Protocol;
using OperatorPanel.ViewModels.Inputs;
using OperatorPanel.ViewModels.Tests.Fakes;

namespace OperatorPanel.ViewModels.Tests.Inputs;

public sealed class InputsViewModelTests : IAsyncDisposable
{
    private readonly PanelFixture _panel = new();
    private readonly InputsViewModel _inputs;

    public InputsViewModelTests() => _inputs = new InputsViewModel(_panel.Session);

    [Fact]
    public void Groups_InputsInTwoBytes_OneGroupPerByteInBitOrder()
    {
        _inputs.Groups.Select(g => (g.Title, string.Join(" ", g.Points.Select(p => p.Address)))).Should().Equal(
            ("Filler IB0", "I0.0 I0.1 I0.5"),
            ("Filler IB1", "I1.2"));
        _inputs.Groups[0].Points[0].Should().Match<LampViewModel>(p =>
            p.Symbol == "StartButton" && p.Comment == "StartButton comment" && p.State == LampState.Bad && p.QualityText == "not read yet");
    }

    [Fact]
    public async Task Refresh_InputsSet_LampsGoodWithTheirValues()
    {
        await _panel.ConnectAsync();
        _panel.Plc.Memory.I[0] = 0b0010_0001; // I0.0 and I0.5

        await _panel.RefreshAsync();

        _inputs.Groups.SelectMany(g => g.Points).Select(p => (p.Address, p.State, p.Quality)).Should().Equal(
            ("I0.0", LampState.On, ValueQuality.Good),
            ("I0.1", LampState.Off, ValueQuality.Good),
            ("I0.5", LampState.On, ValueQuality.Good),
            ("I1.2", LampState.Off, ValueQuality.Good));
    }

    [Fact]
    public async Task Refresh_PortVanished_LampsStaleKeepingTheLastValue()
    {
        await _panel.ConnectAsync();
        _panel.Plc.Memory.SetBit(ProtocolArea.I, 0, 0, true);
        await _panel.RefreshAsync();

        _panel.Transport.Vanished = true;
        await _panel.RefreshAsync();

        var start = _inputs.Groups[0].Points[0];
        start.State.Should().Be(LampState.StaleOn);
        start.Quality.Should().Be(ValueQuality.Stale);
        start.QualityText.Should().StartWith("PortUnavailable");
        _inputs.Groups[0].Points[1].State.Should().Be(LampState.StaleOff);
    }

    public async ValueTask DisposeAsync() => await _panel.DisposeAsync();
}
