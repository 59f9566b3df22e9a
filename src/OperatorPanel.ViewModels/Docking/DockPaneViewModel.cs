using CommunityToolkit.Mvvm.ComponentModel;
using CommunityToolkit.Mvvm.Input;

namespace OperatorPanel.ViewModels.Docking;

/// <summary>
/// One dockable window as the docking host shows it: visible or hidden (View menu), docked to a side or floating,
/// its size. The host binds to these and writes back what the user did with the mouse (splitter, window move).
/// </summary>
public sealed partial class DockPaneViewModel : ObservableObject
{
    public DockPaneViewModel(PaneLayout layout, string title, string automationId)
    {
        ArgumentNullException.ThrowIfNull(layout);
        Id = layout.Id;
        Title = title;
        AutomationId = automationId;
        FloatCommand = new RelayCommand(() => Placement = DockPlacement.Floating, () => Placement != DockPlacement.Floating);
        DockCommand = new RelayCommand<DockPlacement>(p => Placement = p, p => p != Placement);
        Apply(layout);
    }

    public DockPaneId Id { get; }

    public string Title { get; }

    /// <summary>Stable UI automation id of the pane (e.g. "InputsPane").</summary>
    public string AutomationId { get; }

    [ObservableProperty]
    public partial bool IsVisible { get; set; }

    [ObservableProperty]
    [NotifyPropertyChangedFor(nameof(IsFloating))]
    [NotifyCanExecuteChangedFor(nameof(FloatCommand), nameof(DockCommand))]
    public partial DockPlacement Placement { get; set; }

    public bool IsFloating => Placement == DockPlacement.Floating;

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

    [RelayCommand]
    private void Hide() => IsVisible = false;

    public PaneLayout Capture() => new(Id, IsVisible, Placement, DockedSize, Float, Order);

    public void Apply(PaneLayout layout)
    {
        ArgumentNullException.ThrowIfNull(layout);
        IsVisible = layout.IsVisible;
        Placement = layout.Placement;
        DockedSize = layout.DockedSize;
        Float = layout.Float;
        Order = layout.Order;
    }
}
