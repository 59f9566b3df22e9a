using OperatorPanel.ViewModels.Mvvm;

namespace OperatorPanel.ViewModels.Docking;

/// <summary>
/// One dockable window as the docking host shows it: visible or hidden (View menu), docked to a side or floating,
/// its size. The host binds to these and writes back what the user did with the mouse (splitter, window move).
/// </summary>
public sealed class DockPaneViewModel : ObservableObject
{
    private bool _isVisible;
    private DockPlacement _placement;
    private double _dockedSize;
    private FloatBounds _float;
    private int _order;

    public DockPaneViewModel(PaneLayout layout, string title, string automationId)
    {
        ArgumentNullException.ThrowIfNull(layout);
        Id = layout.Id;
        Title = title;
        AutomationId = automationId;
        Apply(layout);
        HideCommand = new RelayCommand(() => IsVisible = false);
        FloatCommand = new RelayCommand(() => Placement = DockPlacement.Floating, () => Placement != DockPlacement.Floating);
        DockCommand = new RelayCommand<DockPlacement>(p => Placement = p, p => p != Placement);
    }

    public DockPaneId Id { get; }

    public string Title { get; }

    /// <summary>Stable UI automation id of the pane (e.g. "InputsPane").</summary>
    public string AutomationId { get; }

    public bool IsVisible
    {
        get => _isVisible;
        set => SetProperty(ref _isVisible, value);
    }

    public DockPlacement Placement
    {
        get => _placement;
        set
        {
            if (SetProperty(ref _placement, value))
            {
                OnPropertyChanged(nameof(IsFloating));
                FloatCommand?.NotifyCanExecuteChanged();
                DockCommand?.NotifyCanExecuteChanged();
            }
        }
    }

    public bool IsFloating => Placement == DockPlacement.Floating;

    public double DockedSize
    {
        get => _dockedSize;
        set => SetProperty(ref _dockedSize, double.IsFinite(value) ? Math.Max(value, DockLayout.MinimumDockedSize) : _dockedSize);
    }

    public FloatBounds Float
    {
        get => _float;
        set => SetProperty(ref _float, value.Normalized());
    }

    public int Order
    {
        get => _order;
        set => SetProperty(ref _order, value);
    }

    public IRelayCommand HideCommand { get; }

    public IRelayCommand FloatCommand { get; }

    /// <summary>Parameter: the <see cref="DockPlacement"/> to dock to.</summary>
    public IRelayCommand DockCommand { get; }

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
