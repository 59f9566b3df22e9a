using OperatorPanel.ViewModels.Docking;

namespace OperatorPanel.ViewModels.Tests.Docking;

public sealed class WindowPlacementTests
{
    private static readonly (double, double, double, double) OneScreen = (0, 0, 1280, 800);

    [Fact]
    public void FitTo_WindowOnTheScreen_StaysAsItWas()
    {
        new WindowPlacement(100, 50, 1000, 700, true).FitTo(OneScreen).Should().Be(new WindowPlacement(100, 50, 1000, 700, true));
    }

    [Fact]
    public void FitTo_MonitorUnpluggedSinceTheLastRun_MovesTheWindowBackOntoTheDesktop()
    {
        // Saved on a second monitor to the right; today only the panel PC's own screen is there.
        new WindowPlacement(1500, 900, 1000, 700, false).FitTo(OneScreen).Should().Be(new WindowPlacement(280, 100, 1000, 700, false));
    }

    [Fact]
    public void FitTo_LargerThanTheDesktopOrTiny_IsClampedToUsableSizes()
    {
        new WindowPlacement(-50, -40, 4000, 3000, false).FitTo(OneScreen).Should().Be(new WindowPlacement(0, 0, 1280, 800, false));
        new WindowPlacement(10, 10, 5, 5, false).FitTo(OneScreen).Should().Be(new WindowPlacement(10, 10, WindowPlacement.MinimumWidth, WindowPlacement.MinimumHeight, false));
    }

    [Fact]
    public void FitTo_PositionNotANumber_LeftToTheSystem()
    {
        var fitted = WindowPlacement.Default.FitTo(OneScreen);

        fitted.Left.Should().Be(double.NaN);
        fitted.Top.Should().Be(double.NaN);
        (fitted.Width, fitted.Height).Should().Be((1280, 800));
    }
}
