using OperatorPanel.ViewModels.Docking;

namespace OperatorPanel.ViewModels.Tests.Docking;

public sealed class DockFitTests
{
    /// <summary>What Wine gives the panel's window on a 1280x800 screen (client area) and the menu, banner and status bar.</summary>
    private const double PanelPcWidth = 1272;
    private const double PanelPcHeight = 773;
    private const double Chrome = 92;

    [Fact]
    public void Regions_RoomForAll_KeepTheSizesThePanesAskFor()
    {
        DockFit.Regions(1262, DockFit.CentreMinimumWidth, DockFit.SideMinimum, 260, 260).Should().Equal(260, 260);
    }

    [Fact]
    public void Regions_CentreShortOfItsMinimum_SidesShrinkInProportionButNotBelowTheirMinimum()
    {
        // Room for the sides: 720 - 420 = 300 of the 400 asked, so three quarters each; 75 is raised to the 100 asked.
        DockFit.Regions(720, 420, 200, 300, 100).Should().Equal(225, 100);
    }

    [Fact]
    public void Regions_NoPaneOnOneSide_ThatSideStaysEmptyAndTheOtherKeepsItsMinimum()
    {
        DockFit.Regions(500, 420, 200, 0, 300).Should().Equal(0, 200);
    }

    [Fact]
    public void Regions_LowWindow_AlarmsPaneGivesWayDownToItsMinimum()
    {
        DockFit.Regions(655, DockFit.CentreMinimumHeight, DockFit.BottomMinimum, 360).Should().Equal(360);
        DockFit.Regions(500, DockFit.CentreMinimumHeight, DockFit.BottomMinimum, 360).Should().Equal(240);
        DockFit.Regions(300, DockFit.CentreMinimumHeight, DockFit.BottomMinimum, 360).Should().Equal(200);
    }

    [Fact]
    public void Zoom_PanelPc1280x800DefaultLayout_IsTheLargestStepAtWhichEveryRegionKeepsItsMinimum()
    {
        // Height decides: 773 / (92 + 205 + 260) = 1.39, down to the step 1.35; the width would allow 1272 / 830 = 1.53.
        DockFit.Zoom(PanelPcWidth, PanelPcHeight, Chrome, (260, 260, 360)).Should().BeApproximately(1.35, 1e-9);
    }

    [Fact]
    public void Zoom_FullHdWindow_IsTheFullLargeDisplayZoom()
    {
        DockFit.Zoom(1920, 1050, Chrome, (260, 260, 360)).Should().Be(DockFit.LargeDisplayZoom);
    }

    [Fact]
    public void Zoom_WindowSmallerThanTheMinimums_NeverShrinksBelowOne()
    {
        DockFit.Zoom(640, 480, Chrome, (260, 260, 360)).Should().Be(1);
        DockFit.Zoom(0, 0, Chrome, (260, 260, 360)).Should().Be(1);
    }
}
