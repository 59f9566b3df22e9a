using System.ComponentModel;
using System.Windows;
using System.Windows.Automation;
using System.Windows.Controls;
using System.Windows.Data;
using OperatorPanel.ViewModels.Docking;

namespace OperatorPanel.App.Docking;

/// <summary>
/// Plain-WPF docking (the registry copy serves no AvalonDock): four regions (left, right, bottom, centre) with tabs and
/// splitters, and a window of its own for each floating pane. All state is in <see cref="DockingViewModel"/>; this
/// class only places the views where the view model says and writes back what the mouse did (splitters, moves).
/// </summary>
public sealed class DockHost : ContentControl
{
    private readonly Grid _grid = new();
    private readonly Dictionary<DockPlacement, TabControl> _regions = [];
    private readonly Dictionary<string, TabItem> _tabs = [];
    private readonly Dictionary<string, FloatingPaneWindow> _floating = [];
    private DockingViewModel? _docking;
    private Window? _owner;

    public DockHost()
    {
        foreach (var placement in new[] { DockPlacement.Left, DockPlacement.Right, DockPlacement.Bottom, DockPlacement.Center })
        {
            var tabs = new TabControl { TabStripPlacement = placement == DockPlacement.Center ? Dock.Top : Dock.Bottom };
            AutomationProperties.SetAutomationId(tabs, $"Dock{placement}Region");
            _regions[placement] = tabs;
        }

        BuildGrid();
        Content = _grid;
        // The window (or the Large display zoom) changed the room: the regions share it anew (DockFit).
        SizeChanged += (_, _) => SizeRegions();
    }

    /// <summary>
    /// Shows the panes of <paramref name="docking"/>: each pane's <see cref="DockPaneViewModel.Content"/> in a content
    /// control, drawn by the DataTemplate for its type (App.xaml), made once and moved between its tab and its window.
    /// </summary>
    public void Initialize(DockingViewModel docking, Window owner)
    {
        ArgumentNullException.ThrowIfNull(docking);
        ArgumentNullException.ThrowIfNull(owner);
        _docking = docking;
        _owner = owner;
        foreach (var pane in docking.Panes)
        {
            var view = new ContentControl { Focusable = false, IsTabStop = false };
            view.SetBinding(ContentProperty, new Binding(nameof(DockPaneViewModel.Content)) { Source = pane });
            var tab = new TabItem { Header = new DockPaneHeader(pane), Content = view, DataContext = pane };
            AutomationProperties.SetAutomationId(tab, pane.AutomationId);
            _tabs[pane.ContentId] = tab;
            pane.PropertyChanged += OnPaneChanged;
        }

        // A floating pane's window is owned by the main window, which can own windows only once it has been shown: a
        // layout saved with a floating pane is arranged again when the owner is loaded.
        if (!owner.IsLoaded)
        {
            owner.Loaded += OnOwnerLoaded;
        }

        Arrange();
    }

    /// <summary>At exit, after the layout is saved: closes floating windows without hiding their panes.</summary>
    public void CloseFloatingWindows()
    {
        foreach (var id in _floating.Keys.ToList())
        {
            CloseFloating(id, _tabs[id]);
        }
    }

    private void OnOwnerLoaded(object sender, RoutedEventArgs e)
    {
        _owner!.Loaded -= OnOwnerLoaded;
        Arrange();
    }

    private void OnPaneChanged(object? sender, PropertyChangedEventArgs e)
    {
        if (e.PropertyName is nameof(DockPaneViewModel.IsVisible) or nameof(DockPaneViewModel.Placement) or nameof(DockPaneViewModel.Order))
        {
            Arrange();
        }
    }

    private void Arrange()
    {
        if (_docking is null)
        {
            return;
        }

        foreach (var region in _regions.Values)
        {
            region.Items.Clear();
        }

        foreach (var pane in _docking.Panes.OrderBy(p => p.Order))
        {
            var tab = _tabs[pane.ContentId];
            if (pane.IsVisible && pane.IsFloating)
            {
                TryFloat(pane, tab);
                continue;
            }

            CloseFloating(pane.ContentId, tab);
            if (pane.IsVisible)
            {
                _regions[pane.Placement].Items.Add(tab);
            }
        }

        foreach (var region in _regions.Values.Where(r => r.Items.Count > 0 && r.SelectedIndex < 0))
        {
            region.SelectedIndex = 0;
        }

        SizeRegions();
    }

    /// <summary>
    /// A window WPF refuses to show (whatever the saved layout held) must not leave the panel without its panes: the
    /// layout goes back to the default, after this arrangement, and the shell says so in one line.
    /// </summary>
    private void TryFloat(DockPaneViewModel pane, TabItem tab)
    {
        try
        {
            Float(pane, tab);
        }
        catch (InvalidOperationException failure)
        {
            if (_floating.Remove(pane.ContentId, out var window))
            {
                tab.Content = window.Release();
            }

            var docking = _docking!;
            Dispatcher.BeginInvoke(() => docking.ResetAfterFailure(failure.Message));
        }
    }

    private void Float(DockPaneViewModel pane, TabItem tab)
    {
        if (_floating.ContainsKey(pane.ContentId) || _owner is not { IsLoaded: true } owner)
        {
            return;
        }

        var view = (UIElement)tab.Content;
        tab.Content = null;
        var window = new FloatingPaneWindow(pane, view, _docking!) { Owner = owner };
        _floating[pane.ContentId] = window;
        window.Show();
    }

    private void CloseFloating(string contentId, TabItem tab)
    {
        if (!_floating.Remove(contentId, out var window))
        {
            return;
        }

        tab.Content = window.Release();
        window.Close();
    }

    /// <summary>Docked sizes as the panes ask, shrunk in proportion when the room leaves the centre less than its minimum (DockFit).</summary>
    private void SizeRegions()
    {
        if (_docking is null)
        {
            return;
        }

        var columns = _grid.ColumnDefinitions;
        var rows = _grid.RowDefinitions;
        var (left, right, bottom) = (Shown(DockPlacement.Left), Shown(DockPlacement.Right), Shown(DockPlacement.Bottom));
        var splitters = (left > 0 ? DockFit.SplitterSize : 0) + (right > 0 ? DockFit.SplitterSize : 0);
        var sides = DockFit.Regions(ActualWidth - splitters, DockFit.CentreMinimumWidth, DockFit.SideMinimum, left, right);
        var below = DockFit.Regions(ActualHeight - (bottom > 0 ? DockFit.SplitterSize : 0), DockFit.CentreMinimumHeight, DockFit.BottomMinimum, bottom);
        columns[0].Width = new GridLength(sides[0]);
        columns[1].Width = new GridLength(left > 0 ? DockFit.SplitterSize : 0);
        columns[3].Width = new GridLength(right > 0 ? DockFit.SplitterSize : 0);
        columns[4].Width = new GridLength(sides[1]);
        rows[1].Height = new GridLength(bottom > 0 ? DockFit.SplitterSize : 0);
        rows[2].Height = new GridLength(below[0]);
    }

    /// <summary>The size a docked region's panes ask for; 0 when no pane is docked there.</summary>
    private double Shown(DockPlacement placement) => _regions[placement].Items.Count == 0 ? 0 : _docking!.RegionSize(placement);

    private void BuildGrid()
    {
        foreach (var _ in Enumerable.Range(0, 5))
        {
            _grid.ColumnDefinitions.Add(new ColumnDefinition());
        }

        _grid.ColumnDefinitions[2].Width = new GridLength(1, GridUnitType.Star);
        _grid.RowDefinitions.Add(new RowDefinition { Height = new GridLength(1, GridUnitType.Star) });
        _grid.RowDefinitions.Add(new RowDefinition());
        _grid.RowDefinitions.Add(new RowDefinition());

        // The sides run the window's full height and the bottom region sits under the centre only: the Inputs and
        // Outputs lists keep their height when Alarms is docked below Memory (every point of a CPU 226 at 1280x800).
        Place(_regions[DockPlacement.Left], 0, 0, rowSpan: 3);
        Place(_regions[DockPlacement.Center], 0, 2);
        Place(_regions[DockPlacement.Right], 0, 4, rowSpan: 3);
        Place(_regions[DockPlacement.Bottom], 2, 2);
        AddSplitter(0, 1, DockPlacement.Left, vertical: true);
        AddSplitter(0, 3, DockPlacement.Right, vertical: true);
        AddSplitter(1, 2, DockPlacement.Bottom, vertical: false);
    }

    private void Place(UIElement element, int row, int column, int rowSpan = 1)
    {
        Grid.SetRow(element, row);
        Grid.SetColumn(element, column);
        Grid.SetRowSpan(element, rowSpan);
        _grid.Children.Add(element);
    }

    private void AddSplitter(int row, int column, DockPlacement region, bool vertical)
    {
        var splitter = new GridSplitter
        {
            HorizontalAlignment = HorizontalAlignment.Stretch,
            VerticalAlignment = VerticalAlignment.Stretch,
            ResizeDirection = vertical ? GridResizeDirection.Columns : GridResizeDirection.Rows,
            ResizeBehavior = GridResizeBehavior.PreviousAndNext,
        };
        AutomationProperties.SetAutomationId(splitter, $"Dock{region}Splitter");
        splitter.DragCompleted += (_, _) => RememberSize(region);
        Place(splitter, row, column, vertical ? 3 : 1);
    }

    /// <summary>A splitter moved: every pane in that region takes the region's new size.</summary>
    private void RememberSize(DockPlacement region)
    {
        var size = region switch
        {
            DockPlacement.Left => _grid.ColumnDefinitions[0].ActualWidth,
            DockPlacement.Right => _grid.ColumnDefinitions[4].ActualWidth,
            DockPlacement.Bottom or DockPlacement.Center or DockPlacement.Floating => _grid.RowDefinitions[2].ActualHeight,
        };
        foreach (var tab in _regions[region].Items.Cast<TabItem>())
        {
            ((DockPaneViewModel)tab.DataContext).DockedSize = size;
        }
    }
}
