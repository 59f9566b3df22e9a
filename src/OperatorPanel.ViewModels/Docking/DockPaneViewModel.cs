using CommunityToolkit.Mvvm.ComponentModel;
using CommunityToolkit.Mvvm.Input;

namespace OperatorPanel.ViewModels.Docking;

/// <summary>
/// One dockable window, the only pane type (AvalonDock's MVVM pattern without AvalonDock): its <see cref="Content"/>
/// (a view model; the App shows it through the DataTemplate for its type), <see cref="Title"/> for the tab and the View
/// menu, <see cref="ContentId"/> keying the saved layout, and where it is: visible or hidden, docked to a side or
/// floating, its size. The docking host binds to these and writes back what the user did with the mouse.
/// </summary>
public sealed partial class DockPaneViewModel : ObservableObject
{
    /// <param name="contentId">Stable key of the pane in the saved layout ("Inputs"); never shown, never renamed.</param>
    /// <param name="title">The tab's and the View menu's text.</param>
    /// <param name="content">The pane's view model.</param>
    /// <param name="placement">Where the default layout docks it.</param>
    /// <param name="dockedSize">Its default width (left, right) or height (bottom), device-independent pixels.</param>
    /// <param name="isVisible">Shown in the default layout.</param>
    /// <param name="order">Its tab position among the panes sharing its place.</param>
    public DockPaneViewModel(string contentId, string title, object content, DockPlacement placement, double dockedSize, bool isVisible = true, int order = 0)
    {
        ArgumentException.ThrowIfNullOrWhiteSpace(contentId);
        ArgumentException.ThrowIfNullOrWhiteSpace(title);
        ArgumentNullException.ThrowIfNull(content);
        ArgumentOutOfRangeException.ThrowIfEqual(placement, DockPlacement.Floating);
        (ContentId, Title, Content) = (contentId, title, content);
        Default = new PaneLayout(contentId, isVisible, placement, dockedSize, FloatBounds.Default, order) { Docked = placement };
        FloatCommand = new RelayCommand(() => Placement = DockPlacement.Floating, () => Placement != DockPlacement.Floating);
        DockCommand = new RelayCommand<DockPlacement>(p => Placement = p, p => p != Placement && p != DockPlacement.Floating);
        DockBackCommand = new RelayCommand(() => Placement = Docked, () => IsFloating);
        Docked = placement;
        Apply(Default);
    }

    public string ContentId { get; }

    public string Title { get; }

    /// <summary>Stable UI automation id of the pane (e.g. "InputsPane").</summary>
    public string AutomationId => ContentId + "Pane";

    /// <summary>The pane's view model; replaced when the pane shows another object (the Alarms of a new project).</summary>
    [ObservableProperty]
    public partial object Content { get; set; }

    /// <summary>The pane in the default layout (View > Reset window layout).</summary>
    public PaneLayout Default { get; }

    [ObservableProperty]
    public partial bool IsVisible { get; set; }

    [ObservableProperty]
    [NotifyPropertyChangedFor(nameof(IsFloating))]
    [NotifyCanExecuteChangedFor(nameof(FloatCommand), nameof(DockCommand), nameof(DockBackCommand))]
    public partial DockPlacement Placement { get; set; }

    public bool IsFloating => Placement == DockPlacement.Floating;

    /// <summary>Where the pane was last docked: <see cref="DockBackCommand"/> (the floating window's Dock button) returns it there.</summary>
    public DockPlacement Docked { get; private set; }

    public double DockedSize
    {
        get;
        set => SetProperty(ref field, double.IsFinite(value) ? Math.Max(value, DockLayout.MinimumDockedSize) : field);
    }

    public FloatBounds Float
    {
        get;
        set => SetProperty(ref field, value.Normalized());
    }

    [ObservableProperty]
    public partial int Order { get; set; }

    public IRelayCommand FloatCommand { get; }

    /// <summary>Parameter: the <see cref="DockPlacement"/> to dock to.</summary>
    public IRelayCommand DockCommand { get; }

    /// <summary>A floating pane back to where it was docked.</summary>
    public IRelayCommand DockBackCommand { get; }

    [RelayCommand]
    private void Hide() => IsVisible = false;

    partial void OnPlacementChanged(DockPlacement value)
    {
        if (value != DockPlacement.Floating)
        {
            Docked = value;
        }
    }

    public PaneLayout Capture() => new(ContentId, IsVisible, Placement, DockedSize, Float, Order) { Docked = Docked };

    public void Apply(PaneLayout layout)
    {
        ArgumentNullException.ThrowIfNull(layout);
        IsVisible = layout.IsVisible;
        Placement = layout.Placement;
        Docked = layout.Docked ?? Default.Placement;
        if (Placement != DockPlacement.Floating)
        {
            Docked = Placement;
        }

        DockedSize = layout.DockedSize;
        Float = layout.Float;
        Order = layout.Order;
    }
}
