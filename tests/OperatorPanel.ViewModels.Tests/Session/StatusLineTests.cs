using OperatorPanel.TestKit;
using OperatorPanel.ViewModels.Session;
using OperatorPanel.ViewModels.Tests.Fakes;

namespace OperatorPanel.ViewModels.Tests.Session;

public sealed class StatusLineTests
{
    private readonly ManualTimeProvider _clock = new();

    [Fact]
    public void Show_Success_ExpiresAfterTenSeconds()
    {
        using var line = new StatusLine(_clock, new InlineDispatcher());

        line.Show("Saved to line.opproj");
        _clock.Advance(StatusLine.InfoLifetime - TimeSpan.FromMilliseconds(1));
        line.Text.Should().Be("Saved to line.opproj");
        _clock.Advance(TimeSpan.FromMilliseconds(1));

        line.Text.Should().Be(StatusLine.IdleText);
        line.IsError.Should().BeFalse();
        StatusLine.InfoLifetime.Should().Be(TimeSpan.FromSeconds(10));
    }

    [Fact]
    public void ShowError_ThenSuccess_TheSuccessReplacesTheErrorAndIsNotRed()
    {
        using var line = new StatusLine(_clock, new InlineDispatcher());

        line.ShowError("Not connected: COM3 is missing");
        line.IsError.Should().BeTrue();
        line.Show("Q0.0 (Conveyor): 1 written and confirmed by the PLC");

        line.IsError.Should().BeFalse("a success is never shown red");
        line.Text.Should().Be("Q0.0 (Conveyor): 1 written and confirmed by the PLC");
        _clock.Advance(StatusLine.InfoLifetime);
        line.Text.Should().Be(StatusLine.IdleText, "the old error does not come back when the success expires");
    }

    [Fact]
    public void ShowError_Failure_StaysAMinuteThenExpires()
    {
        using var line = new StatusLine(_clock, new InlineDispatcher());

        line.ShowError("IDENTIFY failed: no answer");
        _clock.Advance(StatusLine.InfoLifetime);
        line.IsError.Should().BeTrue();
        _clock.Advance(StatusLine.ErrorLifetime - StatusLine.InfoLifetime);

        (line.Text, line.IsError).Should().Be((StatusLine.IdleText, false));
    }

    [Fact]
    public void Show_NewMessageBeforeTheOldExpires_TheNewOneGetsItsFullTime()
    {
        using var line = new StatusLine(_clock, new InlineDispatcher());

        line.Show("first");
        _clock.Advance(TimeSpan.FromSeconds(8));
        line.Show("second");
        _clock.Advance(TimeSpan.FromSeconds(8));

        line.Text.Should().Be("second");
    }
}
